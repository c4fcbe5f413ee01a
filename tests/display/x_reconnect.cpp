#include "x_reconnect.h"

#include <X11/Xlib.h>

namespace resect::test {

int failedReconnects(int cycles) {
    int failed = 0;
    for (int i = 0; i < cycles; ++i) {
        Display* display = XOpenDisplay(nullptr);
        if (!display) {
            ++failed;
            continue;
        }
        XCloseDisplay(display);
    }
    return failed;
}

} // namespace resect::test
