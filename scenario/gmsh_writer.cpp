// Gmsh .msh export, formats 2.2 and 4.1, ASCII and binary (layouts as gmsh_reader.cpp
// describes them, from the Gmsh manual's "MSH file format" section).
//
// What is written:
//   nodes      current positions, node tag = index + 1, never merged (nodes separated by a
//              cut stay distinct even where they coincide)
//   tets       element type 4, element tag = tet index + 1, in mesh order
//   pieces     piece p (connected component) is volume entity p + 1 in physical group p + 1
//              named "piece p"; 4.1 lists the volume entities with their bounding boxes in
//              $Entities (no lower-dimensional entities: Gmsh reads such files and re-saves
//              them). A node belongs to the entity of its piece (unused nodes to entity 1);
//              node and element blocks follow mesh order, so one entity may have several
//              blocks and a file read back gives the same node and tet order.
//   $NodeData  views "reference_position" (3), "mass" (1), "velocity" (3)
//   $ElementData views "quality" (radius ratio) and "piece"
// ASCII doubles are the shortest exact text (detail::exactText): a round trip is exact.

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

static_assert(std::endian::native == std::endian::little,
              "the binary Gmsh writer assumes a little-endian host");

constexpr int kGmshTet4 = 4;

/// Builds the file in memory; fields are text or little-endian binary as the variant asks.
class MshWriter {
public:
    MshWriter(const TetMesh& mesh, bool v41, bool binary)
        : m_mesh(mesh), m_v41(v41), m_binary(binary), m_attributes(tetAttributes(mesh)) {
        m_entities = std::max(m_attributes.pieceCount, 1);
        m_nodeEntity.assign(static_cast<std::size_t>(mesh.nodeCount()), -1);
        for (std::size_t t = 0; t < mesh.tets().size(); ++t)
            for (int n : mesh.tets()[t])
                if (m_nodeEntity[static_cast<std::size_t>(n)] < 0)
                    m_nodeEntity[static_cast<std::size_t>(n)] = m_attributes.piece[t];
        for (int& e : m_nodeEntity)
            e = std::max(e, 0);
    }

    std::string write() {
        format();
        physicalNames();
        if (m_v41) {
            entities();
            nodes41();
            elements41();
        } else {
            nodes22();
            elements22();
        }
        const auto ref = m_mesh.referencePositions();
        const auto vel = m_mesh.velocities();
        const auto mass = m_mesh.masses();
        nodeData("reference_position", 3, [&](int n, int c) { return ref[n][c]; });
        nodeData("mass", 1, [&](int n, int) { return mass[n]; });
        nodeData("velocity", 3, [&](int n, int c) { return vel[n][c]; });
        elementData("quality", [&](int t) { return m_attributes.quality[t]; });
        elementData("piece", [&](int t) { return double(m_attributes.piece[t]); });
        return std::move(m_out);
    }

private:
    // --- fields: ASCII tokens are separated by a space, records end with line()
    void integer(std::int64_t v) { // int
        if (m_binary)
            raw(static_cast<std::int32_t>(v));
        else
            token(std::to_string(v));
    }
    void size(std::int64_t v) { // size_t
        if (m_binary)
            raw(static_cast<std::uint64_t>(v));
        else
            token(std::to_string(v));
    }
    void real(double v) {
        if (m_binary)
            raw(v);
        else
            token(exactText(v));
    }
    template <class T> void raw(T v) { m_out.append(reinterpret_cast<const char*>(&v), sizeof v); }
    void token(const std::string& t) {
        if (!m_out.empty() && m_out.back() != '\n')
            m_out += ' ';
        m_out += t;
    }
    /// Ends an ASCII record (binary records have no line ends).
    void line() {
        if (!m_binary)
            m_out += '\n';
    }
    /// Text that stays text in binary files (headers), one line.
    void text(const std::string& t) { m_out += t + '\n'; }
    /// Closes a section whose data may be binary: Gmsh puts a line feed after binary data.
    void end(const char* section) {
        if (m_binary)
            m_out += '\n';
        text(std::string("$End") + section);
    }

    int nodeCount() const { return m_mesh.nodeCount(); }
    int tetCount() const { return static_cast<int>(m_mesh.tets().size()); }

    void format() {
        text("$MeshFormat");
        text(std::string(m_v41 ? "4.1" : "2.2") + (m_binary ? " 1 8" : " 0 8"));
        if (m_binary) {
            raw(std::int32_t{1});
            m_out += '\n';
        }
        text("$EndMeshFormat");
    }

    void physicalNames() {
        text("$PhysicalNames");
        text(std::to_string(m_entities));
        for (int p = 0; p < m_entities; ++p)
            text("3 " + std::to_string(p + 1) + " \"piece " + std::to_string(p) + "\"");
        text("$EndPhysicalNames");
    }

    /// 4.1: volume entity p + 1 with its box (current positions) and physical tag p + 1.
    void entities() {
        std::vector<Vec3> lo(static_cast<std::size_t>(m_entities), Vec3::Zero());
        std::vector<Vec3> hi = lo;
        std::vector<char> any(static_cast<std::size_t>(m_entities), 0);
        for (int n = 0; n < nodeCount(); ++n) {
            const auto e = static_cast<std::size_t>(m_nodeEntity[static_cast<std::size_t>(n)]);
            const Vec3& p = m_mesh.pos(n);
            lo[e] = any[e] ? lo[e].cwiseMin(p) : p;
            hi[e] = any[e] ? hi[e].cwiseMax(p) : p;
            any[e] = 1;
        }
        text("$Entities");
        for (std::int64_t count : {0, 0, 0, m_entities})
            size(count);
        line();
        for (int e = 0; e < m_entities; ++e) {
            integer(e + 1);
            for (int c = 0; c < 3; ++c)
                real(lo[static_cast<std::size_t>(e)][c]);
            for (int c = 0; c < 3; ++c)
                real(hi[static_cast<std::size_t>(e)][c]);
            size(1);
            integer(e + 1);
            size(0); // no bounding surfaces
            line();
        }
        end("Entities");
    }

    /// Maximal runs [begin, end) of consecutive items with the same entity.
    static std::vector<std::pair<int, int>> runs(const std::vector<int>& entityOf) {
        std::vector<std::pair<int, int>> r;
        for (int i = 0; i < static_cast<int>(entityOf.size()); ++i)
            if (r.empty() || entityOf[static_cast<std::size_t>(i)] !=
                                 entityOf[static_cast<std::size_t>(r.back().first)])
                r.push_back({i, i + 1});
            else
                r.back().second = i + 1;
        return r;
    }

    void nodes41() {
        const auto blocks = runs(m_nodeEntity);
        text("$Nodes");
        size(static_cast<std::int64_t>(blocks.size()));
        size(nodeCount());
        size(nodeCount() > 0 ? 1 : 0);
        size(nodeCount());
        line();
        for (const auto& [begin, stop] : blocks) {
            integer(3);
            integer(m_nodeEntity[static_cast<std::size_t>(begin)] + 1);
            integer(0); // not parametric
            size(stop - begin);
            line();
            for (int n = begin; n < stop; ++n) {
                size(n + 1);
                line();
            }
            for (int n = begin; n < stop; ++n) {
                for (int c = 0; c < 3; ++c)
                    real(m_mesh.pos(n)[c]);
                line();
            }
        }
        end("Nodes");
    }

    void elements41() {
        const auto blocks = runs(m_attributes.piece);
        text("$Elements");
        size(static_cast<std::int64_t>(blocks.size()));
        size(tetCount());
        size(tetCount() > 0 ? 1 : 0);
        size(tetCount());
        line();
        for (const auto& [begin, stop] : blocks) {
            integer(3);
            integer(m_attributes.piece[static_cast<std::size_t>(begin)] + 1);
            integer(kGmshTet4);
            size(stop - begin);
            line();
            for (int t = begin; t < stop; ++t) {
                size(t + 1);
                for (int n : m_mesh.tets()[static_cast<std::size_t>(t)])
                    size(n + 1);
                line();
            }
        }
        end("Elements");
    }

    void nodes22() {
        text("$Nodes");
        text(std::to_string(nodeCount()));
        for (int n = 0; n < nodeCount(); ++n) {
            integer(n + 1);
            for (int c = 0; c < 3; ++c)
                real(m_mesh.pos(n)[c]);
            line();
        }
        end("Nodes");
    }

    /// 2.2: "tag 4 2 physical elementary nodes..."; binary: one block header for all tets.
    void elements22() {
        text("$Elements");
        text(std::to_string(tetCount()));
        if (m_binary && tetCount() > 0) {
            integer(kGmshTet4);
            integer(tetCount());
            integer(2);
        }
        for (int t = 0; t < tetCount(); ++t) {
            const int group = m_attributes.piece[static_cast<std::size_t>(t)] + 1;
            integer(t + 1);
            if (!m_binary) {
                integer(kGmshTet4);
                integer(2);
            }
            integer(group);
            integer(group);
            for (int n : m_mesh.tets()[static_cast<std::size_t>(t)])
                integer(n + 1);
            line();
        }
        end("Elements");
    }

    /// The ASCII header of a view: name, time 0, time step 0, components, count.
    void viewHeader(const char* section, const char* name, int components, int count) {
        text(section);
        text("1");
        text(std::string("\"") + name + "\"");
        text("1");
        text("0");
        text("3");
        text("0");
        text(std::to_string(components));
        text(std::to_string(count));
    }

    void nodeData(const char* name, int components, const std::function<double(int, int)>& value) {
        viewHeader("$NodeData", name, components, nodeCount());
        for (int n = 0; n < nodeCount(); ++n) {
            integer(n + 1);
            for (int c = 0; c < components; ++c)
                real(value(n, c));
            line();
        }
        end("NodeData");
    }

    void elementData(const char* name, const std::function<double(int)>& value) {
        viewHeader("$ElementData", name, 1, tetCount());
        for (int t = 0; t < tetCount(); ++t) {
            integer(t + 1);
            real(value(t));
            line();
        }
        end("ElementData");
    }

    const TetMesh& m_mesh;
    bool m_v41;
    bool m_binary;
    TetAttributes m_attributes;
    int m_entities = 1;
    std::vector<int> m_nodeEntity; // per node, its entity - 1 (piece; 0 for unused nodes)
    std::string m_out;
};

} // namespace

Status writeGmsh(const std::string& path, const TetMesh& mesh, int version, bool binary) {
    if (version != 22 && version != 41)
        return Status::error(path + ": Gmsh version " + std::to_string(version) +
                             " cannot be written; use 22 (format 2.2) or 41 (format 4.1)");
    return guarded(path, "writing", [&]() -> Status {
        if (Status s = checkWritableMesh(path, mesh); !s)
            return s;
        const std::string bytes = MshWriter(mesh, version == 41, binary).write();
        return writeFileAtomically(path, bytes);
    });
}

} // namespace resect
