#include "scenario/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <random>
#include <system_error>

namespace resect {
namespace {

namespace fs = std::filesystem;

/// Eight random characters [a-z0-9] for a temporary file name.
std::string randomSuffix() {
    static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937_64 engine{std::random_device{}()};
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof(kAlphabet)) - 2);
    std::string s(8, 'x');
    for (char& c : s)
        c = kAlphabet[pick(engine)];
    return s;
}

/// Creates a new, empty file next to `target` named `.STEM.tmp-RANDOM.EXT` and returns its
/// path, or an empty path if no such file could be created (errno describes why).
fs::path createTemporaryNextTo(const fs::path& target) {
    const fs::path folder = target.parent_path();
    const std::string stem = target.stem().string();
    const std::string ext = target.extension().string();
    // A few attempts in case of a name collision with a concurrent writer.
    constexpr int kAttempts = 16;
    for (int i = 0; i < kAttempts; ++i) {
        const fs::path candidate = folder / ("." + stem + ".tmp-" + randomSuffix() + ext);
        // "x": exclusive creation (C11), fails if the file already exists.
        if (std::FILE* f = std::fopen(candidate.c_str(), "wbx")) {
            std::fclose(f);
            return candidate;
        }
        if (errno != EEXIST)
            return {};
    }
    return {};
}

void removeQuietly(const fs::path& p) {
    std::error_code ec;
    fs::remove(p, ec);
}

} // namespace

Status writeAtomically(const std::string& path,
                       const std::function<Status(const std::string& tmpPath)>& write) {
    if (path.empty())
        return Status::error("cannot write: empty file name");
    fs::path tmp;
    try {
        const fs::path target(path);
        if (target.filename().empty())
            return Status::error(path + ": not a file name");
        std::error_code ec;
        if (fs::is_directory(target, ec))
            return Status::error(path + ": is a directory");

        tmp = createTemporaryNextTo(target);
        if (tmp.empty()) {
            const std::string folder =
                target.parent_path().empty() ? std::string(".") : target.parent_path().string();
            return Status::error(path + ": cannot create a temporary file in " + folder + " (" +
                                 std::strerror(errno) + ")");
        }

        Status s = write(tmp.string());
        if (!s.ok()) {
            removeQuietly(tmp);
            if (s.message().find(path) == std::string::npos)
                return Status::error(path + ": " + s.message());
            return s;
        }
        fs::rename(tmp, target, ec);
        if (ec) {
            removeQuietly(tmp);
            return Status::error(path + ": cannot replace the file (" + ec.message() + ")");
        }
        return Status::success();
    } catch (const std::exception& e) {
        if (!tmp.empty())
            removeQuietly(tmp);
        return Status::error(path + ": write failed (" + e.what() + ")");
    } catch (...) {
        if (!tmp.empty())
            removeQuietly(tmp);
        return Status::error(path + ": write failed (unknown error)");
    }
}

Status writeFileAtomically(const std::string& path, std::string_view bytes) {
    return writeAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp, std::ios::binary);
        f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        f.close();
        return f ? Status::success() : Status::error(path + ": cannot write");
    });
}

} // namespace resect
