// Triangle surfaces through assimp. Reading: every mesh instance of the node hierarchy,
// transformed to world coordinates, triangulated (aiProcess_Triangulate), points and lines
// dropped, vertices welded by exact position. Writing: a one-mesh aiScene exported with
// the exporter chosen by extension (OFF, which this assimp build cannot export, is written
// directly), always through writeAtomically.
//
// assimp logs through DefaultLogger, which is a NullLogger unless some code calls
// DefaultLogger::create(); this file never creates one, so nothing is printed.

#include "scenario/surface_io.h"

#include "scenario/assimp_guard.h"
#include "scenario/atomic_file.h"
#include "scenario/mesh_io_detail.h"

#include <assimp/BaseImporter.h>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <unordered_map>
#include <vector>

namespace resect {
namespace {

namespace fs = std::filesystem;
using detail::lowerExtension;

// ---------------------------------------------------------------------------------------
// Reading

/// Hash of a position by its exact bit pattern (-0 is normalised to +0 by the caller).
struct ExactPositionHash {
    std::size_t operator()(const Vec3& p) const {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) {
            std::uint64_t bits = 0;
            const double v = p[i];
            std::memcpy(&bits, &v, sizeof bits);
            h ^= std::hash<std::uint64_t>{}(bits) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        }
        return h;
    }
};
struct ExactPositionEqual {
    bool operator()(const Vec3& a, const Vec3& b) const {
        return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
    }
};

/// Accumulates welded vertices and triangles from the mesh instances of a scene.
class SurfaceBuilder {
public:
    explicit SurfaceBuilder(const std::string& path) : m_path(path) {}

    /// Adds the triangles of `mesh` with its vertices transformed by `toWorld`.
    Status addMesh(const aiMesh& mesh, const aiMatrix4x4& toWorld) {
        const bool hasUv = mesh.HasTextureCoords(0) && mesh.mNumUVComponents[0] >= 2;
        bool addedAny = false;
        m_remap.assign(mesh.mNumVertices, -1);
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3)
                continue; // points and lines (polygons were triangulated)
            Tri tri;
            for (int k = 0; k < 3; ++k) {
                const unsigned v = face.mIndices[k];
                if (v >= mesh.mNumVertices)
                    return Status::error(m_path + ": a face refers to a missing vertex");
                if (m_remap[v] < 0) {
                    const aiVector3D w = toWorld * mesh.mVertices[v];
                    // + 0.0 turns -0 into +0 so that both weld together.
                    const Vec3 p(double(w.x) + 0.0, double(w.y) + 0.0, double(w.z) + 0.0);
                    if (!p.allFinite())
                        return Status::error(m_path + ": a vertex has a non-finite coordinate");
                    const auto [it, inserted] =
                        m_index.try_emplace(p, static_cast<int>(m_surface.positions.size()));
                    if (inserted) {
                        m_surface.positions.push_back(p);
                        const Eigen::Vector2d uv =
                            hasUv ? Eigen::Vector2d(mesh.mTextureCoords[0][v].x,
                                                    mesh.mTextureCoords[0][v].y)
                                  : Eigen::Vector2d::Zero();
                        if (!uv.allFinite())
                            return Status::error(m_path + ": a texture coordinate is not finite");
                        m_surface.uvs.push_back(uv); // kept only if every mesh has uvs
                    }
                    m_remap[v] = it->second;
                }
                tri[k] = m_remap[v];
            }
            addedAny = true;
            // Welding can collapse a triangle whose corners coincide: drop it.
            if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0])
                m_surface.triangles.push_back(tri);
        }
        if (addedAny && !hasUv)
            m_allHaveUv = false;
        return Status::success();
    }

    /// Walks the node hierarchy, adding every mesh instance in world coordinates.
    Status addNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, int depth) {
        // assimp validates the scene graph, but a cycle would recurse forever: bound it.
        constexpr int kMaxNodeDepth = 1000;
        if (depth > kMaxNodeDepth)
            return Status::error(m_path + ": the node hierarchy is too deep");
        const aiMatrix4x4 toWorld = parent * node.mTransformation;
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const unsigned m = node.mMeshes[i];
            if (m >= scene.mNumMeshes || !scene.mMeshes[m])
                return Status::error(m_path + ": a node refers to a missing mesh");
            if (Status s = addMesh(*scene.mMeshes[m], toWorld); !s)
                return s;
        }
        for (unsigned c = 0; c < node.mNumChildren; ++c)
            if (node.mChildren[c])
                if (Status s = addNode(scene, *node.mChildren[c], toWorld, depth + 1); !s)
                    return s;
        return Status::success();
    }

    Status finish(TriangleSurface& out) {
        if (m_surface.triangles.empty())
            return Status::error(m_path + ": no triangles");
        if (!m_allHaveUv)
            m_surface.uvs.clear();
        out = std::move(m_surface);
        return Status::success();
    }

private:
    std::string m_path;
    TriangleSurface m_surface;
    std::unordered_map<Vec3, int, ExactPositionHash, ExactPositionEqual> m_index;
    std::vector<int> m_remap; // per vertex of the current mesh: welded index or -1
    bool m_allHaveUv = true;
};

/// Sets every mesh's mPrimitiveTypes from its faces (points, lines, triangles, polygons),
/// checking that each face has indices and that they exist. The scene belongs to the
/// importer, which hands it out as const but lets post-processing steps change it.
Status repairPrimitiveTypes(const std::string& path, const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        aiMesh* mesh = scene.mMeshes[m];
        if (!mesh)
            return Status::error(path + ": a mesh is missing");
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices == 0 || !face.mIndices)
                return Status::error(path + ": a face has no vertices");
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= mesh->mNumVertices)
                    return Status::error(path + ": a face refers to a missing vertex");
            types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
                     : face.mNumIndices == 2 ? aiPrimitiveType_LINE
                     : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                             : aiPrimitiveType_POLYGON;
        }
        mesh->mPrimitiveTypes = types;
    }
    return Status::success();
}

/// Unregisters every importer of `importer` that does not list `ext` (".ply") when some
/// importer does, so that a file is read by its extension's importers only. Otherwise
/// assimp hands a file its importers reject to any importer whose content sniffing accepts
/// it (a 21-byte ".gltf" that mentions "IndexArray" went to the OpenGEX importer, which
/// loops forever on it; tests/fuzz_regressions/surface_gltf). Returns the unregistered
/// importers, which the caller owns: an Importer deletes only its registered ones.
std::vector<std::unique_ptr<Assimp::BaseImporter>> keepImportersFor(Assimp::Importer& importer,
                                                                    const std::string& ext) {
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;
    const std::string bare = ext.empty() ? ext : ext.substr(1);
    if (bare.empty() || !importer.GetImporter(bare.c_str()))
        return removed; // no importer claims the extension: assimp decides by content
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        Assimp::BaseImporter* candidate = importer.GetImporter(i);
        std::set<std::string> extensions;
        candidate->GetExtensionList(extensions);
        if (!extensions.count(bare))
            others.push_back(candidate);
    }
    for (Assimp::BaseImporter* other : others)
        if (importer.UnregisterLoader(other) == aiReturn_SUCCESS)
            removed.emplace_back(other);
    return removed;
}

Status readSurfaceImpl(const std::string& path, TriangleSurface& out) {
    if (Status s = detail::checkRegularFile(path); !s)
        return s;
    if (Status s = detail::checkAssimpInput(path); !s)
        return s;
    Assimp::Importer importer;
    const auto unregistered = keepImportersFor(importer, lowerExtension(path));
    const auto failure = [&] {
        const char* why = importer.GetErrorString();
        return Status::error(path + ": assimp cannot read the file (" +
                             (why && *why ? std::string(why) : std::string("unknown error")) + ")");
    };
    // Import and validate first, triangulate second: Debian's assimp 5.2 is built with
    // assertions that abort the process when a damaged file leaves a mesh's primitive types
    // disagreeing with its faces, so those are made consistent in between.
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (!scene)
        return failure();
    if (Status s = repairPrimitiveTypes(path, *scene); !s)
        return s;
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
    if (!scene)
        return failure();
    if (!scene->mRootNode)
        return Status::error(path + ": no triangles");
    SurfaceBuilder builder(path);
    if (Status s = builder.addNode(*scene, *scene->mRootNode, aiMatrix4x4(), 0); !s)
        return s;
    return builder.finish(out);
}

// ---------------------------------------------------------------------------------------
// Writing

/// Fills `mesh` with the given triangles over all of `surface`'s vertices (vertices as
/// float, as assimp keeps them) and texture coordinates `uvs` (empty: none).
void fillMesh(aiMesh& mesh, const TriangleSurface& surface, const std::vector<Tri>& triangles,
              const std::vector<Eigen::Vector2d>& uvs) {
    mesh.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh.mNumVertices = static_cast<unsigned>(surface.positions.size());
    mesh.mVertices = new aiVector3D[mesh.mNumVertices];
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
        const Vec3& p = surface.positions[i];
        mesh.mVertices[i] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()),
                                       static_cast<ai_real>(p.z()));
    }
    if (!uvs.empty()) {
        mesh.mNumUVComponents[0] = 2;
        mesh.mTextureCoords[0] = new aiVector3D[mesh.mNumVertices];
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            // Vertices off a cut face have NaN cut coordinates: write zeros for them.
            const Eigen::Vector2d uv = uvs[i].allFinite() ? uvs[i] : Eigen::Vector2d::Zero();
            mesh.mTextureCoords[0][i] =
                aiVector3D(static_cast<ai_real>(uv.x()), static_cast<ai_real>(uv.y()), 0);
        }
    }
    mesh.mNumFaces = static_cast<unsigned>(triangles.size());
    mesh.mFaces = new aiFace[mesh.mNumFaces];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        aiFace& face = mesh.mFaces[f];
        face.mNumIndices = 3;
        face.mIndices = new unsigned[3];
        for (int k = 0; k < 3; ++k)
            face.mIndices[k] = static_cast<unsigned>(triangles[f][k]);
    }
}

/// The surface as an assimp scene: one mesh (material "skin") with the texture coordinates
/// `uvs`, and, for a cut surface, a second mesh (material "cut") with the cut faces, whose
/// texture coordinates are the sweep's (u, v) (section 5.2). aiScene's destructor frees
/// everything allocated here with new / new[].
std::unique_ptr<aiScene> makeScene(const TriangleSurface& surface) {
    std::vector<Tri> skin, cut;
    for (int f = 0; f < surface.triangleCount(); ++f)
        (surface.isCutFace(f) ? cut : skin).push_back(surface.triangles[f]);
    const unsigned meshes = cut.empty() || skin.empty() ? 1 : 2;
    auto scene = std::make_unique<aiScene>();
    scene->mRootNode = new aiNode();
    scene->mRootNode->mNumMeshes = meshes;
    scene->mRootNode->mMeshes = new unsigned[meshes];
    scene->mNumMaterials = meshes;
    scene->mMaterials = new aiMaterial*[meshes];
    scene->mNumMeshes = meshes;
    scene->mMeshes = new aiMesh*[meshes];
    const auto add = [&](unsigned i, const char* name, const std::vector<Tri>& triangles,
                         const std::vector<Eigen::Vector2d>& uvs) {
        scene->mRootNode->mMeshes[i] = i;
        scene->mMaterials[i] = new aiMaterial();
        const aiString materialName(name);
        scene->mMaterials[i]->AddProperty(&materialName, AI_MATKEY_NAME);
        scene->mMeshes[i] = new aiMesh();
        scene->mMeshes[i]->mMaterialIndex = i;
        scene->mMeshes[i]->mName = aiString(name);
        fillMesh(*scene->mMeshes[i], surface, triangles, uvs);
    };
    const bool cutUvs = surface.cutUvs.size() == surface.positions.size();
    if (meshes == 2) {
        add(0, "skin", skin, surface.uvs);
        add(1, "cut", cut, cutUvs ? surface.cutUvs : std::vector<Eigen::Vector2d>{});
    } else {
        add(0, skin.empty() ? "cut" : "skin", surface.triangles, surface.uvs);
    }
    return scene;
}

/// Wavefront OBJ, written directly (assimp's OBJ exporter merges vertices that coincide, which
/// would glue the two sides of a cut back together). Every vertex is one "v" line, in order,
/// with 17 significant digits; the skin's texture coordinates are "vt" lines, one per vertex;
/// cut faces (group "cut") use further "vt" lines holding the sweep's (u, v).
Status writeObj(const std::string& path, const TriangleSurface& surface, const std::string& file) {
    std::ofstream os(file, std::ios::binary | std::ios::trunc);
    if (!os)
        return Status::error(path + ": cannot open the temporary file for writing");
    os.precision(17);
    os << "# Resect Studio surface: " << surface.vertexCount() << " vertices, "
       << surface.triangleCount() << " triangles\n";
    for (const Vec3& p : surface.positions)
        os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    const bool skinUv = !surface.uvs.empty();
    if (skinUv)
        for (const Eigen::Vector2d& uv : surface.uvs)
            os << "vt " << uv.x() << ' ' << uv.y() << '\n';
    // Texture coordinates of cut-face corners: one "vt" per vertex on a cut face.
    const bool cutUv = surface.cutUvs.size() == surface.positions.size();
    std::vector<long> cutVt(cutUv ? surface.positions.size() : 0, 0);
    long nextVt = skinUv ? static_cast<long>(surface.uvs.size()) + 1 : 1;
    if (cutUv)
        for (int f = 0; f < surface.triangleCount(); ++f)
            if (surface.isCutFace(f))
                for (int v : surface.triangles[f])
                    if (cutVt[v] == 0 && surface.cutUvs[v].allFinite()) {
                        os << "vt " << surface.cutUvs[v].x() << ' ' << surface.cutUvs[v].y()
                           << '\n';
                        cutVt[v] = nextVt++;
                    }
    const auto face = [&](const Tri& t, bool cut) {
        os << 'f';
        for (int v : t) {
            os << ' ' << v + 1;
            if (cut && cutVt[v] > 0)
                os << '/' << cutVt[v];
            else if (!cut && skinUv)
                os << '/' << v + 1;
        }
        os << '\n';
    };
    os << "g skin\n";
    for (int f = 0; f < surface.triangleCount(); ++f)
        if (!surface.isCutFace(f))
            face(surface.triangles[f], false);
    if (std::find(surface.cutFaces.begin(), surface.cutFaces.end(), 1) != surface.cutFaces.end()) {
        os << "g cut\n";
        for (int f = 0; f < surface.triangleCount(); ++f)
            if (surface.isCutFace(f))
                face(surface.triangles[f], cutUv);
    }
    os.close();
    if (!os)
        return Status::error(path + ": write error");
    return Status::success();
}

/// Exports `scene` with assimp's exporter `formatId` to `file`.
Status assimpExport(const std::string& path, const aiScene& scene, const char* formatId,
                    const std::string& file) {
    Assimp::Exporter exporter;
    if (exporter.Export(&scene, formatId, file) != aiReturn_SUCCESS) {
        const char* why = exporter.GetErrorString();
        return Status::error(path + ": assimp cannot write the file (" +
                             (why && *why ? std::string(why) : std::string("unknown error")) + ")");
    }
    return Status::success();
}

/// Text glTF keeps its buffer in a second file named after the .gltf (NAME.bin) and refers
/// to it by that name. So it is exported under the final name into a private folder next
/// to the target; the buffer is then renamed next to the target (replacing an older one
/// atomically) and the .gltf moved to `tmpPath`, which writeAtomically renames last.
Status exportGltfText(const std::string& path, const aiScene& scene, const std::string& tmpPath) {
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::string hidden(1, '.'); // (not "." + string&&: GCC 12 warns -Wrestrict on it)
    hidden += target.stem().string();
    hidden += ".tmp-XXXXXX";
    std::string pattern = (folder / hidden).string();
    if (!mkdtemp(pattern.data()))
        return Status::error(path + ": cannot create a temporary folder in " + folder.string());
    const fs::path privateDir(pattern);
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code ec;
            fs::remove_all(dir, ec);
        }
    } cleanup{privateDir};

    const fs::path exported = privateDir / target.filename();
    if (Status s = assimpExport(path, scene, "gltf2", exported.string()); !s)
        return s;
    std::vector<fs::path> buffers;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(privateDir, ec))
        if (e.path() != exported)
            buffers.push_back(e.path());
    if (ec)
        return Status::error(path + ": cannot list the temporary folder (" + ec.message() + ")");
    for (const fs::path& b : buffers) {
        fs::rename(b, folder / b.filename(), ec);
        if (ec)
            return Status::error(path + ": cannot move " + b.filename().string() + " next to it (" +
                                 ec.message() + ")");
    }
    fs::rename(exported, tmpPath, ec);
    if (ec)
        return Status::error(path + ": cannot move the written file (" + ec.message() + ")");
    return Status::success();
}

/// OFF (Object File Format), ASCII: "OFF", "V F 0", V lines "x y z", F lines "3 a b c".
/// Coordinates are written with 17 significant digits, so doubles round-trip exactly.
Status writeOff(const std::string& path, const TriangleSurface& surface, const std::string& file) {
    std::ofstream os(file, std::ios::binary | std::ios::trunc);
    if (!os)
        return Status::error(path + ": cannot open the temporary file for writing");
    os.precision(17);
    os << "OFF\n" << surface.positions.size() << ' ' << surface.triangles.size() << " 0\n";
    for (const Vec3& p : surface.positions)
        os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const Tri& t : surface.triangles)
        os << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    os.close();
    if (!os)
        return Status::error(path + ": write error");
    return Status::success();
}

/// Checks that the surface can be written: triangles present, indices valid, coordinates
/// finite, uvs empty or one per vertex.
Status checkWritable(const std::string& path, const TriangleSurface& surface) {
    if (surface.triangles.empty())
        return Status::error(path + ": cannot write a surface without triangles");
    if (!surface.uvs.empty() && surface.uvs.size() != surface.positions.size())
        return Status::error(path + ": the surface has " + std::to_string(surface.uvs.size()) +
                             " texture coordinates for " +
                             std::to_string(surface.positions.size()) + " vertices");
    if (!surface.cutFaces.empty() && surface.cutFaces.size() != surface.triangles.size())
        return Status::error(path + ": the surface's cut-face flags do not match its triangles");
    if (!surface.cutUvs.empty() && surface.cutUvs.size() != surface.positions.size())
        return Status::error(
            path + ": the surface's cut-face texture coordinates do not match its vertices");
    const auto n = static_cast<int>(surface.positions.size());
    for (std::size_t f = 0; f < surface.triangles.size(); ++f)
        for (int v : surface.triangles[f])
            if (v < 0 || v >= n)
                return Status::error(path + ": triangle " + std::to_string(f) +
                                     " refers to vertex " + std::to_string(v) + " of " +
                                     std::to_string(n));
    for (std::size_t i = 0; i < surface.positions.size(); ++i)
        if (!surface.positions[i].allFinite())
            return Status::error(path + ": vertex " + std::to_string(i) +
                                 " has a non-finite coordinate");
    return Status::success();
}

Status writeSurfaceImpl(const std::string& path, const TriangleSurface& surface) {
    const std::string ext = lowerExtension(path);
    // Exporter ids of assimp 5.2; OBJ and OFF are written directly.
    const char* formatId = nullptr;
    if (ext == ".stl")
        formatId = "stlb";
    else if (ext == ".ply")
        formatId = "ply";
    else if (ext == ".glb")
        formatId = "glb2";
    else if (ext == ".gltf")
        formatId = "gltf2";
    else if (ext != ".off" && ext != ".obj")
        return Status::error(path + ": unknown surface extension '" + ext +
                             "'; expected .obj, .stl, .ply, .off, .glb or .gltf");
    if (Status s = checkWritable(path, surface); !s)
        return s;

    if (ext == ".off")
        return writeAtomically(
            path, [&](const std::string& tmp) { return writeOff(path, surface, tmp); });
    if (ext == ".obj")
        return writeAtomically(
            path, [&](const std::string& tmp) { return writeObj(path, surface, tmp); });
    const std::unique_ptr<aiScene> scene = makeScene(surface);
    return writeAtomically(path, [&](const std::string& tmp) {
        if (ext == ".gltf")
            return exportGltfText(path, *scene, tmp);
        return assimpExport(path, *scene, formatId, tmp);
    });
}

} // namespace

Status readSurface(const std::string& path, TriangleSurface& out) {
    return detail::guarded(path, "reading", [&] { return readSurfaceImpl(path, out); });
}

Status writeSurface(const std::string& path, const TriangleSurface& surface) {
    return detail::guarded(path, "writing", [&] { return writeSurfaceImpl(path, surface); });
}

} // namespace resect
