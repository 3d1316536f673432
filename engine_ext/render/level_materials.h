// Resolves a map texture name to an OGRE material: `level/<name>` from media/materials when
// defined there, otherwise a fallback generated once per name (a texgen texture on a clone of
// Obscura/Level), so an unknown texture is never an error. Sky faces (map/surface_rules.h: sky*
// names, Quake 2 SURF_SKY) all get `level/sky`; fence textures (`{` names) are alpha-tested: their
// generated grille discards alpha < 0.5 in the G-buffer pass and in their own shadow caster
// material (a clone of Obscura/ShadowCasterAlphaTest with the same texture).
#pragma once

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
    std::size_t generatedCount() const { return generatedMaterials_.size(); }

private:
    std::string group_;
    std::map<std::string, std::string> cache_;  // lower-cased texture -> material name
    std::vector<Ogre::MaterialPtr> generatedMaterials_;
    std::vector<Ogre::TexturePtr> generatedTextures_;
};

}  // namespace obscura::render
