#pragma once
// Triangle surfaces through assimp: OBJ, STL, PLY, OFF, glTF and everything else assimp
// reads. Vertices at identical positions are welded (STL and some OBJ files repeat them
// per face); texture coordinates are kept when the file has them.

#include "core/mesh/triangle_surface.h"
#include "core/status.h"

#include <string>

namespace resect {

/// Reads every mesh of the file (node transforms applied), triangulated and welded. Errors
/// (missing or unreadable file, no triangles, non-finite coordinates or texture
/// coordinates) name the file.
Status readSurface(const std::string& path, TriangleSurface& out);

/// Writes atomically with the assimp exporter chosen by extension (.obj, .stl, .ply,
/// .glb, .gltf, ...).
Status writeSurface(const std::string& path, const TriangleSurface& surface);

} // namespace resect
