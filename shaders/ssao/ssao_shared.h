// Limits the AO modes' C++ (engine_ext/ssao) and GLSL (shaders/ssao) share: plain #defines valid
// in both. C++: #include "ssao/ssao_shared.h"; GLSL: #include "ssao_shared.h".
#ifndef OBSCURA_SSAO_SHARED_H
#define OBSCURA_SSAO_SHARED_H

// Size of the kernel[] uniform: the seeds used 8-32 samples; the samples knob goes up to this.
#define SSAO_MAX_SAMPLES 32
// Side of the per-pixel rotation texture: 4x4 interleaved rotations, which the blur's 5 taps cover.
#define SSAO_NOISE_SIZE 4

#endif
