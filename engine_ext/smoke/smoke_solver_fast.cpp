// The optimised substep, built twice from smoke_solver_fast_impl.h: for the baseline x86-64
// instruction set (SSE2, 4 floats a vector) and for AVX2 (8 floats a vector), picked at run time
// by what the CPU supports (SmokeSettings::vectorIsa). Both round identically: strict IEEE, no FMA
// (-ffp-contract=off, and the AVX2 path does not enable FMA), and the same operations in the same
// order, so the two give bitwise-equal fields (tested) and a replay recorded on one machine plays
// the same on another (README.md has the step times of both).
//
// Why a pragma and not -mavx2 on a second file: inline functions from the std headers included
// before it stay baseline code, so no AVX2 copy of a shared template can win at link time and
// reach a CPU without AVX2.
// The AVX2 path instantiates the kernels' templates on 8-float vectors; they are always inlined into
// AVX2 code, so the ABI note GCC gives for such a template (-Wpsabi) does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <immintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "smoke/smoke_state.h"
#include "smoke/thread_pool.h"

namespace obscura::smoke {

namespace isa_baseline {
#define OBSCURA_SMOKE_LANES 4
#define OBSCURA_SMOKE_MOVEMASK(m) _mm_movemask_ps(reinterpret_cast<__m128>(m))
#include "smoke/smoke_solver_fast_impl.h"
#undef OBSCURA_SMOKE_LANES
#undef OBSCURA_SMOKE_MOVEMASK
}  // namespace isa_baseline

#if defined(__x86_64__) && defined(__GNUC__)
#define OBSCURA_SMOKE_HAS_AVX2_PATH 1
#pragma GCC push_options
#pragma GCC target("avx2")
namespace isa_avx2 {
#define OBSCURA_SMOKE_LANES 8
#define OBSCURA_SMOKE_MOVEMASK(m) _mm256_movemask_ps(reinterpret_cast<__m256>(m))
#include "smoke/smoke_solver_fast_impl.h"
#undef OBSCURA_SMOKE_LANES
#undef OBSCURA_SMOKE_MOVEMASK
}  // namespace isa_avx2
#pragma GCC pop_options
#endif

bool avx2PathAvailable() {
#ifdef OBSCURA_SMOKE_HAS_AVX2_PATH
    static const bool supported = __builtin_cpu_supports("avx2");
    return supported;
#else
    return false;
#endif
}

namespace {
bool useAvx2(VectorIsa isa) {
#ifdef OBSCURA_SMOKE_HAS_AVX2_PATH
    return isa == VectorIsa::Best && avx2PathAvailable();
#else
    (void)isa;
    return false;
#endif
}
}  // namespace

#ifdef OBSCURA_SMOKE_HAS_AVX2_PATH
#define OBSCURA_SMOKE_DISPATCH(isa, call) (useAvx2(isa) ? isa_avx2::call : isa_baseline::call)
#else
#define OBSCURA_SMOKE_DISPATCH(isa, call) (isa_baseline::call)
#endif

void substepFast(SmokeState& s, const SmokeSettings& st, ThreadPool& pool, float dt) {
    OBSCURA_SMOKE_DISPATCH(st.vectorIsa, substepFastImpl(s, st, pool, dt));
}

float maxOutflowRate(SmokeState& s, ThreadPool& pool) {
    return OBSCURA_SMOKE_DISPATCH(VectorIsa::Best, maxOutflowRateImpl(s, pool));  // a maximum: the same from either build
}

PressureSolveStats solvePressureFast(SmokeState& s, const SmokeSettings& st, ThreadPool& pool) {
    return OBSCURA_SMOKE_DISPATCH(st.vectorIsa, solvePressureImpl(s, st, pool));
}

}  // namespace obscura::smoke
