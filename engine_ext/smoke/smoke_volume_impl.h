// SmokeVolume's private data (shared by smoke_volume.cpp and smoke_volume_query.cpp).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "smoke/smoke_volume.h"
#include "smoke/thread_pool.h"

namespace obscura::smoke {

struct SmokeVolume::Impl {
    SmokeSettings settings;
    SmokeState state;
    std::shared_ptr<ThreadPool> pool;
    std::vector<float> transmittance;  // 1 until computeTransmittance()
    std::vector<float> opticalDepth;   // scratch of computeTransmittance()
    std::vector<float> skyVisibility;  // 1 until computeSkyVisibility()
    std::vector<float> exportScratch;  // the exported density (exportRG8 / exportRGFloat)
    std::vector<std::size_t> exportSource;  // the free cell each exported cell's values come from
};

}  // namespace obscura::smoke
