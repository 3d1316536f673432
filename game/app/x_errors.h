// X errors in the game's words. Xlib's default handlers print a bare "X Error of failed request"
// and exit(1) on any protocol error, even one as harmless as a BadDrawable for a window that is
// going away under load. Ours name the error with the `obscura:` prefix; protocol errors are
// reported (the first few, then a count at exit) and play goes on; losing the display connection
// cannot be survived (Xlib exits when its handler returns), so it says so and exits with 1.
#pragma once

namespace obscura {

// Installs both handlers for the rest of the process (after OGRE and SDL opened the display).
void installXErrorHandlers();
// How many protocol errors were reported since.
unsigned long xErrorCount();

}  // namespace obscura
