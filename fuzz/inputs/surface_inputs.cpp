// Fuzz targets of the surface reader (scenario/surface_io.h, through assimp), one per
// extension, since assimp picks its importer by extension first: surface_obj, surface_stl,
// surface_ply, surface_off, surface_gltf (text glTF; buffers must be data: URIs, as the
// input is one file) and surface_glb.

#include "fuzz/fuzz_inputs.h"

#include "scenario/surface_io.h"

namespace resect::fuzz {
namespace {

Outcome readAs(const char* fileName, std::span<const std::uint8_t> input) {
    const std::string path = writeScratchFile(fileName, input);
    TriangleSurface surface;
    if (Status s = readSurface(path, surface); !s) {
        if (!surface.positions.empty() || !surface.triangles.empty())
            return Outcome::broken("the surface was changed by a failed read");
        return rejected(s, {path});
    }
    if (std::string bad = checkSurface(surface); !bad.empty())
        return Outcome::broken(bad);
    return Outcome::accepted();
}

Outcome objInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.obj", input);
}
Outcome stlInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.stl", input);
}
Outcome plyInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.ply", input);
}
Outcome offInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.off", input);
}
Outcome gltfInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.gltf", input);
}
Outcome glbInput(std::span<const std::uint8_t> input) {
    return readAs("fuzz.glb", input);
}

} // namespace

RESECT_FUZZ_TARGET(surface_obj, objInput);
RESECT_FUZZ_TARGET(surface_stl, stlInput);
RESECT_FUZZ_TARGET(surface_ply, plyInput);
RESECT_FUZZ_TARGET(surface_off, offInput);
RESECT_FUZZ_TARGET(surface_gltf, gltfInput);
RESECT_FUZZ_TARGET(surface_glb, glbInput);

} // namespace resect::fuzz
