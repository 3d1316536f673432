// The sun's share of a surface's direct irradiance, per unit sun colour and before its shadow:
// computed by the G-buffer pass (shaders/level/level.frag) and again by the lighting pass for a
// normal a decal bends (shaders/frame/lighting.frag), so both agree to the bit on the same normal.
// Lambert's cosine, no wrap: the wrap (0.2) that kept faces turned from the sun off the ambient
// floor is the baked bounce's job now (engine_ext/lightbake), and it added up to 0.17 of the sun
// to grazing faces (the courtyard's error against the path-traced reference).
float sunShare(float ndotl) { return max(ndotl, 0.0); }
