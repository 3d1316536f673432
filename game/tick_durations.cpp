// See tick_durations.h.
#include "tick_durations.h"

#include <algorithm>
#include <cmath>

namespace obscura {

int ticksFor(double seconds, double tickRate) {
    return std::max(1, static_cast<int>(std::lround(seconds * tickRate)));
}

TickDurations::TickDurations(double tickRate)
    : tickSeconds(1.0 / tickRate),
      headlessTicks(ticksFor(kDefaultHeadlessSeconds, tickRate)),
      sparkTicks(ticksFor(kSparkSeconds, tickRate)),
      muzzleFlashTicks(ticksFor(kMuzzleFlashSeconds, tickRate)),
      smokeStepTicks(ticksFor(kSmokeStepSeconds, tickRate)),
      hissFadeTicks(ticksFor(kHissFadeSeconds, tickRate)),
      centrePrintTicks(ticksFor(kCentrePrintSeconds, tickRate)),
      // (1 / rate) / 0.25 is exactly 1/15 at 60 Hz: dividing by a power of two is exact.
      hitMarkerFadePerTick((1.0 / tickRate) / kHitMarkerFadeSeconds) {}

}  // namespace obscura
