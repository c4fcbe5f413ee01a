#pragma once
// EdgeKeyTable: a map from edge keys (two node indices in 64 bits, as edgeKey(a, b) of
// cut_types.h makes them) to ints in one flat open-addressing array. The steps of a cut meet every
// edge near the sweep once or twice; std::unordered_map allocated a node per edge there and cost
// more than the work on the edge. clear() empties only the slots used, so a table reused for many
// small key sets (the faces around each cut vertex) costs in proportion to the keys, not to its
// size.

#include <cstdint>
#include <utility>
#include <vector>

namespace resect {

class EdgeKeyTable {
public:
    /// Room for `expectedKeys` keys before the table grows.
    explicit EdgeKeyTable(std::size_t expectedKeys = 0) { reserve(expectedKeys); }

    /// The value stored for `key`, after storing `value` there if the key was absent; second
    /// is true if it was absent. `key` must not be 0 (the key of the pair (0, 0), not an edge).
    std::pair<int, bool> tryInsert(std::uint64_t key, int value) {
        if (2 * (m_used.size() + 1) > m_keys.size())
            grow();
        std::size_t i = slotOf(key);
        while (m_keys[i] != 0) {
            if (m_keys[i] == key)
                return {m_values[i], false};
            i = (i + 1) & m_mask;
        }
        m_keys[i] = key;
        m_values[i] = value;
        m_used.push_back(i);
        return {value, true};
    }

    std::size_t size() const { return m_used.size(); }

    /// Removes every key, touching only the slots in use.
    void clear() {
        for (std::size_t i : m_used)
            m_keys[i] = 0;
        m_used.clear();
    }

    void reserve(std::size_t keys) {
        std::size_t capacity = 16;
        while (capacity < 2 * keys)
            capacity *= 2;
        if (capacity > m_keys.size())
            rehash(capacity);
    }

private:
    std::size_t slotOf(std::uint64_t key) const {
        // Multiplicative hashing (by 2^64 / phi) spreads the keys of neighbouring node pairs.
        return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & m_mask;
    }
    void grow() { rehash(m_keys.empty() ? 16 : 2 * m_keys.size()); }
    void rehash(std::size_t capacity) {
        std::vector<std::uint64_t> keys(capacity, 0);
        std::vector<int> values(capacity);
        std::vector<std::size_t> used;
        used.reserve(m_used.size());
        m_mask = capacity - 1;
        for (std::size_t old : m_used) {
            std::size_t i = slotOf(m_keys[old]);
            while (keys[i] != 0)
                i = (i + 1) & m_mask;
            keys[i] = m_keys[old];
            values[i] = m_values[old];
            used.push_back(i);
        }
        m_keys.swap(keys);
        m_values.swap(values);
        m_used.swap(used);
    }

    std::vector<std::uint64_t> m_keys; ///< 0: empty slot
    std::vector<int> m_values;
    std::vector<std::size_t> m_used; ///< slots in use, in insertion order
    std::size_t m_mask = 0;
};

} // namespace resect
