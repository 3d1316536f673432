// See stop_signal.h.
#include "stop_signal.h"

namespace obscura {

namespace {
volatile std::sig_atomic_t gPending = 0;

void onSignal(int sig) {
    if (gPending != 0) {  // asked twice: stop now
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    gPending = sig;
}
}  // namespace

StopSignal::StopSignal() {
    gPending = 0;
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;  // a blocking read or GL wait resumes; the loop sees the flag after it
    sigaction(SIGINT, &sa, &previousInt_);
    sigaction(SIGTERM, &sa, &previousTerm_);
}

StopSignal::~StopSignal() {
    sigaction(SIGINT, &previousInt_, nullptr);
    sigaction(SIGTERM, &previousTerm_, nullptr);
}

int StopSignal::pending() { return gPending; }

}  // namespace obscura
