#pragma once
// IndexMarks: one value per index (a mesh node or tet), "clear" unless set since the last reset,
// for the steps of a cut, which mark a few hundred nodes and tets near the sweep of a mesh of up
// to millions. A std::vector sized to the mesh and cleared for every cut costs O(mesh) per cut;
// these marks are kept from use to use (grown to the largest size asked for, never shrunk) and
// reset() clears only the entries set since the last reset (it keeps a list of their indices), so
// after the first use on a mesh a use costs in proportion to the entries it sets. Reading a mark
// is one array read; set() adds a test of the old value.
//
// Not for concurrent use. Typical use, marks kept between cuts on one thread (why thread_local:
// "Marks" at HybridCutter::cut, core/cut/hybrid_cutter.h):
//     thread_local IndexMarks<char> seen;
//     const auto scope = seen.use(mesh.tetCount()); // all clear here; reset when scope ends
//     if (!seen[t]) seen.set(t, 1);

#include <cassert>
#include <cstddef>
#include <vector>

namespace resect {

template <class T>
class IndexMarks {
public:
    /// Marks whose clear value is `clear` (an index never set reads as `clear`).
    explicit IndexMarks(T clear = T{}) : m_clear(clear) {}
    IndexMarks(const IndexMarks&) = delete;
    IndexMarks& operator=(const IndexMarks&) = delete;

    /// Makes indices [0, size) readable, all clear unless set since the last reset. Grows to
    /// size plus a quarter (room for what later cuts add to the mesh without reallocating), never
    /// shrinks: a smaller size keeps the marks as they are.
    void grow(std::size_t size) {
        if (size > m_values.size())
            m_values.resize(size + size / 4, m_clear);
    }

    /// The mark of index i (i below the largest size grown to).
    const T& operator[](std::size_t i) const {
        assert(i < m_values.size());
        return m_values[i];
    }

    /// Sets the mark of index i; remembers i for reset() when a clear entry becomes set (an entry
    /// set back to the clear value stays listed, and is listed again if set once more).
    void set(std::size_t i, const T& value) {
        assert(i < m_values.size());
        if (m_values[i] == m_clear && !(value == m_clear))
            m_setIndices.push_back(i);
        m_values[i] = value;
    }

    /// Clears every entry set since the last reset, touching only those: one write per set()
    /// that made a clear entry set.
    void reset() {
        for (std::size_t i : m_setIndices)
            m_values[i] = m_clear;
        m_setIndices.clear();
    }

    /// Entries reset() will write (set() calls that made a clear entry set since the last reset).
    std::size_t pendingResets() const { return m_setIndices.size(); }
    /// Indices readable: the largest size grown to, plus headroom.
    std::size_t size() const { return m_values.size(); }
    const T& clearValue() const { return m_clear; }

    /// A use of the marks over [0, size) that resets them when it ends (also on an early return).
    class Scope {
    public:
        explicit Scope(IndexMarks& marks) : m_marks(marks) {}
        ~Scope() {
            m_marks.reset();
            m_marks.m_inUse = false;
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        IndexMarks& m_marks;
    };

    /// Grows to `size` and returns the scope of this use; every mark is clear at its start (a
    /// use that did not reset is reset here, in proportion to what it set). Uses may not nest.
    [[nodiscard]] Scope use(std::size_t size) {
        assert(!m_inUse && "IndexMarks used twice at once");
        m_inUse = true;
        reset();
        grow(size);
        return Scope(*this);
    }

private:
    std::vector<T> m_values;
    /// Indices set since the last reset, once per set() that made a clear entry set.
    std::vector<std::size_t> m_setIndices;
    T m_clear;
    bool m_inUse = false;
};

} // namespace resect
