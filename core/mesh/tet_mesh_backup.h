#pragma once
// TetMeshBackup: exact undo of an edit of a TetMesh (a cut), in time proportional to what the
// edit touched, not to the mesh.
//
// While a backup is open, the mesh records the state of every tet and every existing node
// before its first change: a tet before replaceTet, a node's data (reference and current
// position, velocity, mass) and its adjacency list before setNodePosition, setMass, or an
// adjacency change by addTet or replaceTet. restore() puts them back and removes the appended
// nodes and tets: the mesh is then bit-identical to what it was, the order of every node's
// adjacency list included (so later edits run exactly as if this one never happened).
//
// The backup undoes itself when destroyed unless commit() was called: the "backup that undoes
// itself on failure" of STYLE.md 14. Backups nest; restoring an outer one first restores the
// ones opened inside it.
//
// Node data written through the spans (positions(), masses(), ...) is not recorded: while a
// backup is open, change existing nodes only through setNodePosition and setMass. New nodes
// (index >= nodeCount() at opening) may be written freely; they are removed on restore.

#include "core/mesh/tet_mesh.h"

#include <unordered_set>
#include <vector>

namespace resect {

class TetMeshBackup {
public:
    /// Opens a backup of `mesh` (which must outlive it).
    explicit TetMeshBackup(TetMesh& mesh);
    /// Restores unless committed.
    ~TetMeshBackup();
    TetMeshBackup(const TetMeshBackup&) = delete;
    TetMeshBackup& operator=(const TetMeshBackup&) = delete;

    /// Puts the mesh back as it was at opening, and closes the backup.
    void restore();
    /// Keeps the edit and closes the backup (its records are dropped).
    void commit();
    bool isOpen() const { return m_mesh != nullptr; }

    /// Node and tet counts at opening.
    int nodesBefore() const { return m_nodes; }
    int tetsBefore() const { return m_tets; }
    /// How many existing tets and nodes were recorded (for tests and statistics).
    int recordedTets() const { return static_cast<int>(m_savedTets.size()); }
    int recordedNodes() const { return static_cast<int>(m_savedNodes.size()); }

private:
    friend class TetMesh;
    void saveTet(int t);
    void saveNode(int n);
    void close();

    struct NodeRecord {
        int node;
        Vec3 ref, pos, vel;
        double mass;
        std::vector<int> tets;
    };

    TetMesh* m_mesh;
    int m_nodes, m_tets;
    std::vector<std::pair<int, Tet>> m_savedTets;
    std::vector<NodeRecord> m_savedNodes;
    std::unordered_set<int> m_seenTets, m_seenNodes;
};

} // namespace resect
