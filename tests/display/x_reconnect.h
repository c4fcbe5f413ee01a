#pragma once
// Opens and closes a connection to the X display `cycles` times (Xlib kept out of the test's
// Qt code: its macros clash with Qt's names).

namespace resect::test {

/// How many of `cycles` XOpenDisplay calls failed, each connection closed before the next.
int failedReconnects(int cycles);

} // namespace resect::test
