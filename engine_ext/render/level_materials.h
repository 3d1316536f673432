// Resolves a map texture name to an OGRE material: `level/<name>` from media/materials when
// defined there, otherwise a fallback generated once per name (a texgen texture on a clone of
// Obscura/Level), so an unknown texture is never an error.
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

    // The material name for a map texture (case-insensitive). Never throws for unknown names.
    const std::string& resolve(const std::string& texture);
    std::size_t generatedCount() const { return generatedMaterials_.size(); }

private:
    std::string group_;
    std::map<std::string, std::string> cache_;  // lower-cased texture -> material name
    std::vector<Ogre::MaterialPtr> generatedMaterials_;
    std::vector<Ogre::TexturePtr> generatedTextures_;
};

}  // namespace obscura::render
