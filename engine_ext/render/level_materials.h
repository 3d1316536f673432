// Resolves a map texture name to an OGRE material: `level/<name>` from media/materials when
// defined there, otherwise a fallback generated once per name (a texgen texture on a clone of
// Obscura/Level), so an unknown texture is never an error. Sky faces (map/surface_rules.h: sky*
// names, Quake 2 SURF_SKY) all get `level/sky`; fence textures (`{` names) are alpha-tested: their
// generated grille discards alpha < 0.5 in the G-buffer pass and in their own shadow caster
// material (a clone of Obscura/ShadowCasterAlphaTest with the same texture).
#pragma once

#include "map/level.h"

#include <OgreMaterial.h>
#include <OgreTexture.h>

#include <map>
#include <string>
#include <vector>

namespace obscura::render {

class LevelMaterials {
public:
    explicit LevelMaterials(std::string resourceGroup);
    ~LevelMaterials();  // destroys the generated materials and textures
    LevelMaterials(const LevelMaterials&) = delete;
    LevelMaterials& operator=(const LevelMaterials&) = delete;

    // The material name for a map texture (case-insensitive); `sky` (LevelPolygon::sky) picks the
    // sky material whatever the name. Never throws for unknown names.
    const std::string& resolve(const std::string& texture, bool sky = false);
    // The material for a liquid face: alpha >= 1 the texture's own (opaque, in the G-buffer);
    // below, a clone of Obscura/Liquid (forward, translucent) with the texture's albedo, the alpha,
    // and a glow for lava and teleporters. One per texture and alpha (in 1/1000 steps).
    const std::string& resolveLiquid(const std::string& texture, map::LiquidKind kind, double alpha);
    // The material of a baked face (a lightmap chart, engine_ext/lightbake): resolve()'s, cloned
    // once per texture with level.frag's `baked` set, so it reads its light from the lightmaps.
    const std::string& resolveBaked(const std::string& texture);
    std::size_t generatedCount() const { return generatedMaterials_.size(); }
    // The translucent liquid materials made so far (the frame binds the G-buffer's depth to them).
    const std::vector<Ogre::MaterialPtr>& liquidMaterials() const { return liquidMaterials_; }

private:
    std::string group_;
    std::map<std::string, std::string> cache_;  // lower-cased texture -> material name
    std::vector<Ogre::MaterialPtr> generatedMaterials_;
    std::vector<Ogre::TexturePtr> generatedTextures_;
    std::vector<Ogre::MaterialPtr> liquidMaterials_;  // also in generatedMaterials_
};

}  // namespace obscura::render
