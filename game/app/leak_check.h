// The sanitizer build's leak check of a run: memory lost while playing, looked for at the end of
// the run, before teardown, while every library (OGRE's plugins, Mesa's driver) is still loaded
// so each leak's stack names its module and lsan.supp can match it. At exit those libraries are
// unloaded and their allocations show as "<unknown module>", which no suppression can name.
#pragma once

namespace obscura {

// True when LeakSanitizer is built in, enabled (ASAN_OPTIONS detect_leaks=1) and found memory
// that nothing reaches any more (its report is on stderr). False in every other build.
bool runLeakedMemory();

}  // namespace obscura
