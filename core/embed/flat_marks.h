#pragma once
// Scratch tables for the surface cut that are cleared in O(1) (an epoch stamp per slot) and keep
// their memory between cuts, so that a cut allocates nothing per element and costs in proportion
// to what it touches, not to the surface:
//  * EdgeTable: a value per edge key (two vertex indices packed in 64 bits), open addressing
//    with linear probing;
//  * StampedMarks: a value per index (vertex, triangle) with "absent" for indices not set since
//    the last clear (arrays whose untouched pages cost nothing).
// (core/mesh/index_marks.h and edge_key_table.h serve the tet cut in the same spirit, with a
// list of set indices instead of stamps; the two were written in parallel and not merged.)

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace resect {

/// A map from 64-bit edge keys to int values, cleared in O(1); grows by doubling (keeping
/// the memory between uses).
class EdgeTable {
public:
    void clear() {
        m_size = 0;
        if (++m_epoch == 0) {
            std::fill(m_stamp.begin(), m_stamp.end(), 0u);
            m_epoch = 1;
        }
    }
    int size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    /// The value of key, or null.
    int* find(std::uint64_t key) {
        if (m_keys.empty())
            return nullptr;
        for (std::size_t i = slotOf(key);; i = (i + 1) & m_mask) {
            if (m_stamp[i] != m_epoch)
                return nullptr;
            if (m_keys[i] == key)
                return &m_values[i];
        }
    }
    const int* find(std::uint64_t key) const { return const_cast<EdgeTable*>(this)->find(key); }
    bool contains(std::uint64_t key) const { return find(key) != nullptr; }
    /// The value of key, or `absent`.
    int get(std::uint64_t key, int absent = 0) const {
        const int* v = find(key);
        return v ? *v : absent;
    }
    /// Inserts (key, value) if key is absent. Returns the value slot and whether it was added.
    std::pair<int*, bool> insert(std::uint64_t key, int value) {
        if (2 * (m_size + 1) > static_cast<int>(m_keys.size()))
            rehash(m_keys.empty() ? 64 : 2 * m_keys.size());
        for (std::size_t i = slotOf(key);; i = (i + 1) & m_mask) {
            if (m_stamp[i] != m_epoch) {
                m_stamp[i] = m_epoch;
                m_keys[i] = key;
                m_values[i] = value;
                ++m_size;
                return {&m_values[i], true};
            }
            if (m_keys[i] == key)
                return {&m_values[i], false};
        }
    }
    /// Room for `entries` keys without growing.
    void reserve(int entries) {
        std::size_t capacity = m_keys.empty() ? 64 : m_keys.size();
        while (capacity < 2 * static_cast<std::size_t>(entries))
            capacity *= 2;
        if (capacity > m_keys.size())
            rehash(capacity);
    }
    /// Sets the value of key (inserting it if absent).
    void set(std::uint64_t key, int value) { *insert(key, value).first = value; }

private:
    std::size_t slotOf(std::uint64_t key) const {
        key ^= key >> 29;
        key *= 0xbf58476d1ce4e5b9ull;
        key ^= key >> 32;
        return static_cast<std::size_t>(key) & m_mask;
    }
    void rehash(std::size_t capacity) {
        std::vector<std::uint64_t> keys(capacity);
        std::vector<int> values(capacity);
        std::vector<std::uint32_t> stamp(capacity, 0u);
        std::swap(keys, m_keys);
        std::swap(values, m_values);
        std::swap(stamp, m_stamp);
        const std::uint32_t old = m_epoch;
        m_epoch = 1;
        m_mask = capacity - 1;
        m_size = 0;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (stamp[i] == old)
                insert(keys[i], values[i]);
    }

    std::vector<std::uint64_t> m_keys;
    std::vector<int> m_values;
    std::vector<std::uint32_t> m_stamp;
    std::uint32_t m_epoch = 1;
    std::size_t m_mask = 0;
    int m_size = 0;
};

/// value(i) per index i (a vertex, a triangle), set since the last clear() or absent: arrays over
/// the indices with an epoch stamp per index. The arrays come from the allocator without being
/// written (the stamps zeroed by calloc, so fresh pages are the system's zero pages until used),
/// so a fresh one (the first cut of a copied surface) costs in proportion to the indices a cut
/// marks, not to the surface.
class StampedMarks {
public:
    StampedMarks() = default;
    /// Scratch, not state: a copy starts empty, an assignment keeps what it has.
    StampedMarks(const StampedMarks&) {}
    StampedMarks& operator=(const StampedMarks&) { return *this; }
    ~StampedMarks() {
        std::free(m_stamp);
        std::free(m_value);
    }
    void clear() {
        if (++m_epoch == 0) {
            std::fill(m_stamp, m_stamp + m_capacity, 0u);
            m_epoch = 1;
        }
    }
    /// Room for indices below `size`, with headroom (growing copies the arrays).
    void grow(int size) {
        if (size <= m_capacity)
            return;
        const int capacity = size + size / 4 + 1024;
        auto* stamp = static_cast<std::uint32_t*>(std::calloc(capacity, sizeof(std::uint32_t)));
        auto* value = static_cast<int*>(std::malloc(static_cast<std::size_t>(capacity) * sizeof(int)));
        if (!stamp || !value)
            throw std::bad_alloc();
        if (m_capacity > 0) {
            std::copy(m_stamp, m_stamp + m_capacity, stamp);
            std::copy(m_value, m_value + m_capacity, value);
        }
        std::free(m_stamp);
        std::free(m_value);
        m_stamp = stamp;
        m_value = value;
        m_capacity = capacity;
    }
    bool has(int i) const { return i < m_capacity && m_stamp[i] == m_epoch; }
    /// The value, or `absent` if not set.
    int get(int i, int absent = 0) const { return has(i) ? m_value[i] : absent; }
    void set(int i, int value) {
        grow(i + 1);
        m_stamp[i] = m_epoch;
        m_value[i] = value;
    }
    /// Sets i if absent; returns true if it was.
    bool insert(int i, int value = 1) {
        if (has(i))
            return false;
        set(i, value);
        return true;
    }
    int& at(int i) { return m_value[i]; }  ///< the value of a present index

private:
    std::uint32_t* m_stamp = nullptr;
    int* m_value = nullptr;
    int m_capacity = 0;
    std::uint32_t m_epoch = 1;
};

} // namespace resect
