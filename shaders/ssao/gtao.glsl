// GTAO's slice math (Jimenez, Wu, Pesce, Jarabo 2016): engine_ext/ssao/gtao.h line for line, where
// tests/ssao/gtao_test.cpp checks it against numeric integration. Angles in a slice are measured
// from the view vector V, positive towards the slice direction; n is the projected normal's angle.
const float kGtaoHalfPi = 1.5707963;

// a(h) = 1/4 (-cos(2h - n) + cos n + 2h sin n): the cosine-weighted visibility from V out to h.
float gtaoInnerIntegral(float h, float n)
{
    return 0.25 * (-cos(2.0 * h - n) + cos(n) + 2.0 * h * sin(n));
}

// A horizon clamped to the hemisphere about the projected normal.
float gtaoClampHorizon(float h, float n)
{
    return n + clamp(h - n, -kGtaoHalfPi, kGtaoHalfPi);
}

// The inner integral over the unoccluded arc h1 .. h2 of a slice (times |n_p| outside).
float gtaoSliceIntegral(float h1, float h2, float n)
{
    return gtaoInnerIntegral(gtaoClampHorizon(h1, n), n) + gtaoInnerIntegral(gtaoClampHorizon(h2, n), n);
}

// The horizon angle of one side (+1 towards the slice direction, -1 away) from the highest elevation
// found there (sin of the angle above the tangent plane): acos(e / |n_p|) from the projected
// normal, clamped to the side.
float gtaoHorizonFromElevation(float elevation, float n, float npLength, float side)
{
    float alpha = acos(clamp(elevation / max(npLength, 1e-4), 0.0, 1.0));
    return side > 0.0 ? max(n + alpha, 0.0) : min(n - alpha, 0.0);
}

// The multi-bounce fit (the paper's eq. 10): visibility x of a surface of albedo rho, raised to what
// its inter-reflected light gives back; x for black, 1 at x = 1.
float gtaoMultiBounce(float x, float albedo)
{
    float a = 2.0404 * albedo - 0.3324;
    float b = -4.7951 * albedo + 0.6417;
    float c = 2.7552 * albedo + 0.6903;
    return max(x, ((x * a + b) * x + c) * x);
}
