// See level_materials.h.
#include "render/level_materials.h"

#include "map/liquid.h"
#include "map/surface_rules.h"
#include "texgen/texgen.h"

#include <OgreImage.h>
#include <OgreMaterialManager.h>
#include <OgreLogManager.h>
#include <OgreGpuProgramParams.h>
#include <OgrePass.h>
#include <OgreTechnique.h>
#include <OgreTextureManager.h>
#include <OgreTextureUnitState.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace obscura::render {

namespace {
// Generated fallback textures: 128 px is enough for a 64-texel Quake texture seen up close and
// costs 64 KiB each; e3m4 has about 150 distinct names.
constexpr int kFallbackTextureSize = 128;
// Fence texels below half alpha are holes (Quake's fences are 1-bit masks; 0.5 keeps a mipmapped
// grille's bars, 61 % coverage, texgen.cpp).
constexpr float kFenceAlphaCutoff = 0.5f;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}
}  // namespace

LevelMaterials::LevelMaterials(std::string resourceGroup) : group_(std::move(resourceGroup)) {}

LevelMaterials::~LevelMaterials() {
    auto& mm = Ogre::MaterialManager::getSingleton();
    for (auto& m : generatedMaterials_) mm.remove(m);
    auto& tm = Ogre::TextureManager::getSingleton();
    for (auto& t : generatedTextures_) tm.remove(t);
}

const std::string& LevelMaterials::resolve(const std::string& texture, bool sky) {
    static const std::string kSky = "level/sky";
    if (sky) return kSky;
    const std::string key = lower(texture);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;

    auto& mm = Ogre::MaterialManager::getSingleton();
    const std::string authored = "level/" + key;
    if (mm.resourceExists(authored, group_)) return cache_[key] = authored;

    // Fallback: a texture generated from the name on a clone of the base level material.
    const Image pixels = texgen::generateTexture(key, kFallbackTextureSize);
    Ogre::Image image;
    image.loadDynamicImage(const_cast<Ogre::uchar*>(pixels.rgba.data()), static_cast<Ogre::uint32>(pixels.width),
                           static_cast<Ogre::uint32>(pixels.height), 1, Ogre::PF_BYTE_RGBA);
    const std::string name = "generated/" + key;
    Ogre::TexturePtr tex = Ogre::TextureManager::getSingleton().loadImage(name, group_, image);
    generatedTextures_.push_back(tex);

    Ogre::MaterialPtr base = mm.getByName("Obscura/Level", group_);
    if (!base) throw std::runtime_error("material Obscura/Level is missing (media/materials/level.material)");
    Ogre::MaterialPtr mat = base->clone(name);
    // Every technique (the lit one and the AO G-buffer one) samples the albedo.
    for (auto* tech : mat->getTechniques())
        if (auto* unit = tech->getPass(0)->getTextureUnitState("albedo")) unit->setTextureName(name);
    generatedMaterials_.push_back(mat);
    if (map::isFenceTexture(key)) {
        // Holes where alpha < 0.5, in the G-buffer (so the view and AO see through) and in the
        // sun's shadow map (a caster material of its own with the same texture).
        Ogre::MaterialPtr casterBase = mm.getByName("Obscura/ShadowCasterAlphaTest", group_);
        if (!casterBase) throw std::runtime_error("material Obscura/ShadowCasterAlphaTest is missing (media/materials/level.material)");
        Ogre::MaterialPtr caster = casterBase->clone(name + "/caster");
        for (auto* tech : caster->getTechniques())
            if (auto* unit = tech->getPass(0)->getTextureUnitState("albedo")) unit->setTextureName(name);
        generatedMaterials_.push_back(caster);
        for (auto* tech : mat->getTechniques()) {
            tech->getPass(0)->getFragmentProgramParameters()->setNamedConstant("alphaCutoff", kFenceAlphaCutoff);
            tech->setShadowCasterMaterial(caster);
        }
    }
    return cache_[key] = name;
}

const std::string& LevelMaterials::resolveBaked(const std::string& texture) {
    const std::string key = "baked/" + lower(texture);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    auto& mm = Ogre::MaterialManager::getSingleton();
    Ogre::MaterialPtr plain = mm.getByName(resolve(texture), group_);
    if (!plain) throw std::runtime_error("material " + resolve(texture) + " is missing");
    Ogre::MaterialPtr mat = plain->clone(key);
    for (auto* tech : mat->getTechniques()) {
        Ogre::Pass* pass = tech->getPass(0);
        if (!pass->hasFragmentProgram()) continue;
        const auto params = pass->getFragmentProgramParameters();
        if (params->_findNamedConstantDefinition("baked")) params->setNamedConstant("baked", 1.0f);
    }
    generatedMaterials_.push_back(mat);
    return cache_[key] = key;
}

const std::string& LevelMaterials::resolveLiquid(const std::string& rawTexture, map::LiquidKind kind, double alpha) {
    // A Quake 2 liquid is one by its content bits, not its name ("e1u1/lava1", no '*'): with no
    // authored material, its texture is drawn from the kind ("*lava/lava1"), not as a wall.
    const bool authored = Ogre::MaterialManager::getSingleton().resourceExists("level/" + lower(rawTexture), group_);
    const std::string texture = authored || (!rawTexture.empty() && rawTexture[0] == '*')
                                    ? rawTexture
                                    : "*" + std::string(map::liquidName(kind)) + "/" + std::string(map::textureBaseName(rawTexture));
    if (!(alpha < 1.0)) return resolve(texture);
    const long milli = std::lround(std::clamp(alpha, 0.0, 1.0) * 1000.0);
    const std::string key = "liquid/" + lower(texture) + "/" + std::to_string(milli);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;

    // The albedo the opaque material samples (authored or generated).
    auto& mm = Ogre::MaterialManager::getSingleton();
    Ogre::MaterialPtr opaque = mm.getByName(resolve(texture), group_);
    std::string albedo = "default.png";
    if (opaque && opaque->getNumTechniques() > 0)
        if (auto* unit = opaque->getTechnique(0)->getPass(0)->getTextureUnitState("albedo")) albedo = unit->getTextureName();

    Ogre::MaterialPtr base = mm.getByName("Obscura/Liquid", group_);
    if (!base) throw std::runtime_error("material Obscura/Liquid is missing (media/materials/level.material)");
    Ogre::MaterialPtr mat = base->clone(key);
    Ogre::Pass* pass = mat->getTechnique(0)->getPass(0);
    pass->getTextureUnitState("albedo")->setTextureName(albedo);
    const bool glows = kind == map::LiquidKind::Lava || kind == map::LiquidKind::Teleport;
    pass->getFragmentProgramParameters()->setNamedConstant("alpha", static_cast<float>(milli / 1000.0));
    pass->getFragmentProgramParameters()->setNamedConstant("glow", glows ? 1.0f : 0.0f);
    generatedMaterials_.push_back(mat);
    liquidMaterials_.push_back(mat);
    return cache_[key] = key;
}

}  // namespace obscura::render
