#pragma once
// Status: the result of an operation on untrusted input. Empty message means success.
// Degenerate or bad input returns a Status; exceptions never cross layer boundaries.

#include <cstdio>
#include <string>
#include <utility>

namespace resect {

class Status {
public:
    Status() = default;
    static Status success() { return {}; }
    static Status error(std::string message) {
        Status s;
        s.m_message = std::move(message);
        if (s.m_message.empty())
            s.m_message = "unknown error";
        return s;
    }
    bool ok() const { return m_message.empty(); }
    explicit operator bool() const { return ok(); }
    const std::string& message() const { return m_message; }

private:
    std::string m_message;
};

/// A number as messages print it: shortest of %g's forms ("0.5", "1e-06", "100").
inline std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

} // namespace resect
