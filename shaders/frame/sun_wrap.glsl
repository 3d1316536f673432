// The sun's share of a surface's direct irradiance, per unit sun colour and before its shadow:
// computed by the G-buffer pass (shaders/level/level.frag) and again by the lighting pass for a
// normal a decal bends (shaders/frame/lighting.frag), so both agree to the bit on the same normal.
// Wrap lighting (0.2): keeps sunlit back faces from collapsing to the ambient floor.
float sunWrap(float ndotl) { return max((ndotl + 0.2) / 1.2, 0.0); }
