#pragma once
// FNV-1a over raw bytes: the fingerprints of the golden tests (test_cut_golden,
// test_cut_surface_golden), which compare cuts bit for bit with ones recorded earlier.
#include <cstddef>
#include <cstdint>

namespace resect::testing {

struct Fnv1a {
    std::uint64_t h = 1469598103934665603ull;
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i)
            h = (h ^ p[i]) * 1099511628211ull;
    }
};

} // namespace resect::testing
