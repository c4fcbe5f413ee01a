#pragma once
// Anatomy -> simulation-ready coarse tet mesh: the steps shared by `resect mesh`, the demo
// and the studio (check the surface, optionally repair it, orient it, tetrahedralize,
// compute masses).

#include "core/mesh/material.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "core/mesher/tetrahedralize.h"
#include "core/status.h"

#include <string>

namespace resect {

struct AnatomyMeshing {
    MeshingOptions meshing;
    Material material;
    bool repair = false;  ///< fill holes of an open surface instead of refusing it
};

/// Loads a surface file (through assimp) or a built-in sample: `source` is a path, or
/// "sample:polyp" / "sample:myoma".
Status loadAnatomy(const std::string& source, TriangleSurface& out);

/// Checks (and with `repair`, closes) the surface, orients it outward in place, meshes it and
/// sets masses from the material density (Eq. 3). `log` receives notes such as
/// "filled 2 holes". Errors are one sentence naming the problem. `report` (optional)
/// receives what the mesher found and did (tetrahedralize.h).
Status meshAnatomy(TriangleSurface& surface, const AnatomyMeshing& options, TetMesh& out,
                   std::string* log = nullptr, MeshingReport* report = nullptr);

} // namespace resect
