#include "app/x_errors.h"

#include <X11/Xlib.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace obscura {
namespace {

std::atomic<unsigned long> errors{0};
// Enough to see a pattern, few enough not to flood a terminal when one fails every frame.
constexpr unsigned long kReported = 5;

int onProtocolError(Display* display, XErrorEvent* e) {
    const unsigned long n = ++errors;
    if (n <= kReported) {
        char text[256] = "";
        XGetErrorText(display, e->error_code, text, sizeof text);
        std::fprintf(stderr, "obscura: X error: %s (request %d.%d, resource 0x%lx); playing on%s\n", text,
                     e->request_code, e->minor_code, e->resourceid, n == kReported ? " (further X errors only counted)" : "");
    }
    return 0;
}

int onConnectionLost(Display*) {
    const char* name = std::getenv("DISPLAY");
    std::fprintf(stderr, "obscura: lost the connection to the X display (DISPLAY=%s): the X server closed it or went away; exiting\n",
                 name ? name : "unset");
    std::fflush(stderr);
    std::_Exit(1);  // Xlib would exit() anyway; skip destructors that would talk to the dead display
}

}  // namespace

void installXErrorHandlers() {
    XSetErrorHandler(onProtocolError);
    XSetIOErrorHandler(onConnectionLost);
}

unsigned long xErrorCount() { return errors; }

}  // namespace obscura
