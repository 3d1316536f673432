// The phase function of every medium the volumetric pass marches (smoke, the signs' haze):
// Henyey-Greenstein x pi, so that light arriving as the surfaces' irradiance E makes a medium of
// albedo 1 send (pi x phase x E) per unit of opacity: isotropic scattering gives 0.25 E, as a white
// Lambertian surface sends E back. cosTheta: between the view ray and the light's travel.
#ifndef OBSCURA_VOLUME_PHASE
#define OBSCURA_VOLUME_PHASE
float volumePhase(float cosTheta, float g)
{
    float d = 1.0 + g * g - 2.0 * g * cosTheta;
    return 0.25 * (1.0 - g * g) / (d * sqrt(d));
}
#endif
