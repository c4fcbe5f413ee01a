#include "scenario/anatomy.h"

#include "core/mesh/masses.h"
#include "core/mesher/check_surface.h"
#include "core/mesher/samples.h"
#include "scenario/surface_io.h"

namespace resect {

Status loadAnatomy(const std::string& source, TriangleSurface& out) {
    const std::string prefix = "sample:";
    if (source.rfind(prefix, 0) == 0) {
        const std::string name = source.substr(prefix.size());
        const auto sample = sampleFromName(name);
        if (!sample) {
            std::string known;
            for (const auto& n : sampleNames())
                known += (known.empty() ? "" : ", ") + n;
            return Status::error("unknown sample '" + name + "' (known: " + known + ")");
        }
        out = sampleSurface(*sample);
        return Status::success();
    }
    return readSurface(source, out);
}

Status meshAnatomy(TriangleSurface& surface, const AnatomyMeshing& options, TetMesh& out,
                   std::string* log, MeshingReport* report) {
    SurfaceCheck check = checkSurface(surface);
    Status problem = surfaceProblem(check);
    if (!problem.ok() && options.repair && check.borderEdges > 0 && check.nonFiniteVertices == 0 &&
        check.badIndexTriangles == 0) {
        int filled = 0;
        if (Status s = fillHoles(surface, &filled); !s.ok())
            return s;
        if (log)
            *log += "filled " + std::to_string(filled) + " hole(s)\n";
        check = checkSurface(surface);
        problem = surfaceProblem(check);
    }
    if (!problem.ok())
        return problem;
    orientOutward(surface);
    TetMesh mesh;
    if (Status s = tetrahedralize(surface, options.meshing, mesh, report); !s.ok())
        return s;
    computeLumpedMasses(mesh, options.material.density);
    out = std::move(mesh);
    return Status::success();
}

} // namespace resect
