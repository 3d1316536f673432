// See sign_render.h.
#include "signs/sign_render.h"

#include "signs/meshuggah.h"
#include "signs/signs_shared.h"

#include <Ogre.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace obscura::signs {

static_assert(SIGN_HOLE_SLOTS == SIGN_MAX_LIGHTS * SIGN_MAX_HOLES, "signs_shared.h: SIGN_HOLE_SLOTS");

namespace {
constexpr Ogre::uint32 kSurfacesPass = 40;  // media/signs/signs.compositor
const char* const kSurfacesCompositor = "Obscura/Signs/Surfaces";
// The plate's thickness: a sheet of metal or acrylic; its back and edges hide the lamp.
constexpr float kPlateThickness = 0.02f;
// The open diffuser's glow as a share of the irradiance the lamp puts on the plate: an opal
// diffuser passes about a fifth forward, spread over the hemisphere (/ pi); at the defaults
// (6 at 0.3 m) the letters show as ~4 of light, white through the tone map, their colour at the edge.
constexpr float kGlowShare = 0.2f / 3.14159265f;
const char* const kShadowScheme = "SignShadow";
// The lamp's shadow map: 512 texels across the plate's rectangle, a texel ~2 cm at 10 m behind a
// 1 m plate 0.3 m from its lamp (the pillar's edge in the shafts is that sharp); drawn every frame
// (props, doors and the player move), ~1/4 of the G-buffer's pixels at 720p.
constexpr unsigned kShadowSize = SIGN_SHADOW_SIZE;

Ogre::Vector3 ogre(const Vec3& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

Ogre::TexturePtr floatTexture(const std::string& name, int width, int height, const float* texels) {
    Ogre::Image image;
    image.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(const_cast<float*>(texels)), static_cast<Ogre::uint32>(width),
                           static_cast<Ogre::uint32>(height), 1, Ogre::PF_FLOAT32_R);
    return Ogre::TextureManager::getSingleton().loadImage(name, Ogre::RGN_DEFAULT, image, Ogre::TEX_TYPE_2D, 0);
}
}  // namespace

const char* signModeName(SignMode m) {
    return m == SignMode::Off ? "off" : m == SignMode::Meshuggah ? "meshuggah" : "shafts";
}

class SignRender::Shafts : public frame::Technique {
public:
    explicit Shafts(SignRender& r) : r_(r) {}
    std::string folder() const override { return "engine_ext/signs"; }
    frame::Stage stage() const override { return frame::Stage::Volumetrics; }
    std::string compositor() const override {
        return r_.mode_ == SignMode::Shafts && !r_.chosen_.empty() && r_.haze_ > 0 ? frame::kVolumesCompositor : "";
    }
    std::string missingFeature(const frame::Gpu& gpu) const override {
        return gpu.renderTargetFormat(Ogre::PF_FLOAT32_RGBA) ? std::string() : "render targets in PF_FLOAT32_RGBA";
    }
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext&) override {
        if (passId != frame::kVolumesPass) return;
        r_.bindSigns(pass, u);
        u.set("signHaze", r_.haze_);
    }
    std::vector<Output> outputs() const override { return {{"volume", "volumeMap"}}; }

private:
    SignRender& r_;
};

class SignRender::Surfaces : public frame::Technique {
public:
    explicit Surfaces(SignRender& r) : r_(r) {}
    std::string folder() const override { return "engine_ext/signs"; }
    frame::Stage stage() const override { return frame::Stage::Lighting; }
    std::string compositor() const override { return r_.mode_ != SignMode::Off && !r_.chosen_.empty() ? kSurfacesCompositor : ""; }
    void bind(Ogre::uint32 passId, Ogre::Pass& pass, frame::Uniforms& u, const frame::FrameContext& ctx) override {
        if (passId != kSurfacesPass) return;
        frame::setViewRay(u, ctx);
        r_.bindSigns(pass, u);
    }

private:
    SignRender& r_;
};

SignRender::SignRender(Ogre::SceneManager& scene, std::vector<SignSpec> specs, std::vector<SignMask> masks, float haze,
                       Ogre::uint32 shadowExclude)
    : scene_(scene), specs_(std::move(specs)), masks_(std::move(masks)), holes_(specs_.size()), shadowExclude_(shadowExclude),
      haze_(haze), shafts_(std::make_unique<Shafts>(*this)), surfaces_(std::make_unique<Surfaces>(*this)) {
    const float closed = -1.f, lit = 0.f;  // a mask that lets nothing through; a shadow map with nothing in it
    noMask_ = floatTexture("Obscura/Signs/NoMask", 1, 1, &closed);
    noShadow_ = floatTexture("Obscura/Signs/NoShadow", 1, 1, &lit);
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        const SignMask& m = masks_[i];
        maskTextures_.push_back(floatTexture("Obscura/Signs/Mask" + std::to_string(i), m.width, m.height, m.distance.data()));
        buildPlate(i);
        beamLo_.emplace_back();
        beamHi_.emplace_back();
        beamBounds(specs_[i], m, beamLo_.back(), beamHi_.back());
    }
    meshuggah_ = std::make_unique<Meshuggah>(scene_, specs_, masks_);
    if (specs_.empty()) return;
    caster_ = Ogre::MaterialManager::getSingleton().getByName("Obscura/Signs/ShadowCaster");
    if (!caster_) throw std::runtime_error("material Obscura/Signs/ShadowCaster (media/signs/signs.material) is missing");
    caster_->load();
    Ogre::MaterialManager::getSingleton().addListener(this, kShadowScheme);
    auto& tm = Ogre::TextureManager::getSingleton();
    for (std::size_t k = 0; k < SIGN_MAX_LIGHTS; ++k) {
        Shadow s;
        const std::string name = "Obscura/Signs/Shadow" + std::to_string(k);
        s.texture = tm.createManual(name, Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, kShadowSize, kShadowSize, 0, Ogre::PF_FLOAT32_R,
                                    Ogre::TU_RENDERTARGET);
        s.camera = scene_.createCamera(name);
        s.node = scene_.getRootSceneNode()->createChildSceneNode();
        s.node->setFixedYawAxis(false);
        s.node->attachObject(s.camera);
        Ogre::RenderTexture* rt = s.texture->getBuffer()->getRenderTarget();
        rt->setAutoUpdated(false);
        Ogre::Viewport* vp = rt->addViewport(s.camera);
        vp->setClearEveryFrame(true);
        vp->setBackgroundColour(Ogre::ColourValue(0, 0, 0, 1));  // 0: nothing there, lit
        vp->setMaterialScheme(kShadowScheme);
        vp->setShadowsEnabled(false);
        vp->setOverlaysEnabled(false);
        vp->setSkiesEnabled(false);
        vp->setVisibilityMask(~(shadowExclude_ | kPlateVisibilityFlag));
        shadows_.push_back(s);
    }
}

Ogre::Technique* SignRender::handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material*, unsigned short,
                                                  const Ogre::Renderable*) {
    return schemeName == kShadowScheme ? caster_->getTechnique(0) : nullptr;
}

// Slot `slot`'s camera at its sign's lamp, its frustum exactly the plate's rectangle (off-centre
// when the lamp is not behind the centre), and the map drawn.
void SignRender::drawShadow(std::size_t slot) {
    Shadow& sh = shadows_[slot];
    const SignSpec& s = specs_[chosen_[slot]];
    const SignMask& m = masks_[chosen_[slot]];
    const Ogre::Vector3 lamp = ogre(s.lamp), right = ogre(s.right), up = ogre(s.up), facing = ogre(s.facing);
    sh.node->setPosition(lamp);
    // The camera looks down its -Z; seen from the lamp the plate's right is the camera's left
    // (facing = right x up, so (-right, up, -facing) is the right-handed frame).
    sh.node->setOrientation(Ogre::Quaternion(-right, up, -facing));
    const float a = static_cast<float>(std::max(dot(s.centre - s.lamp, s.facing), 1e-3));
    const float near = std::min(0.05f, 0.5f * a);
    // The plate's rectangle relative to the lamp, scaled to the near plane.
    const float cx = -static_cast<float>(dot(s.centre - s.lamp, s.right)), cy = static_cast<float>(dot(s.centre - s.lamp, s.up));
    const float k = near / a, hw = static_cast<float>(m.halfWidth), hh = static_cast<float>(m.halfHeight);
    sh.camera->setNearClipDistance(near);
    sh.camera->setFarClipDistance(static_cast<float>(s.range) + a);
    sh.camera->setFrustumExtents((cx - hw) * k, (cx + hw) * k, (cy + hh) * k, (cy - hh) * k);
    caster_->getTechnique(0)->getPass(0)->getFragmentProgramParameters()->setNamedConstant("lampPosition", lamp);
    Ogre::RenderTexture* rt = sh.texture->getBuffer()->getRenderTarget();
    rt->update();
    // world -> the map's clip space; the texture is stored upside down when the render system flips RTTs.
    Ogre::Matrix4 flip = Ogre::Matrix4::IDENTITY;
    if (rt->requiresTextureFlipping()) flip[1][1] = -1;
    sh.worldToClip = flip * sh.camera->getProjectionMatrix() * sh.camera->getViewMatrix();
}

frame::Technique& SignRender::shafts() { return *shafts_; }
frame::Technique& SignRender::surfaces() { return *surfaces_; }
const std::vector<Ogre::MaterialPtr>& SignRender::meshuggahMaterials() const { return meshuggah_->materials(); }

SignRender::~SignRender() {
    meshuggah_.reset();
    auto& tm = Ogre::TextureManager::getSingleton();
    auto& mm = Ogre::MaterialManager::getSingleton();
    if (caster_) mm.removeListener(this, kShadowScheme);
    for (Shadow& s : shadows_) {
        s.texture->getBuffer()->getRenderTarget()->removeAllViewports();
        s.node->detachAllObjects();
        scene_.destroySceneNode(s.node);
        scene_.destroyCamera(s.camera);
        tm.remove(s.texture);
    }
    for (std::size_t i = 0; i < plates_.size(); ++i) {
        nodes_[i]->detachAllObjects();
        scene_.destroyManualObject(plates_[i]);
        scene_.destroySceneNode(nodes_[i]);
        mm.remove(plateMaterials_[i]);
    }
    for (auto& t : maskTextures_) tm.remove(t);
    tm.remove(noMask_);
    tm.remove(noShadow_);
}

// A thin box: the front face (the plate's plane, facing the room) carries the mask's uv; the back and
// the four edges uv -1 (sign_plate.frag: not open).
void SignRender::buildPlate(std::size_t i) {
    const SignSpec& s = specs_[i];
    const SignMask& m = masks_[i];
    Ogre::MaterialPtr mat = Ogre::MaterialManager::getSingleton().getByName("Obscura/Signs/Plate")->clone("Obscura/Signs/Plate" + std::to_string(i));
    mat->load();
    Ogre::Pass* pass = mat->getTechnique(0)->getPass(0);
    pass->getTextureUnitState("plateMask")->setTexture(maskTextures_[i]);
    const Ogre::GpuProgramParametersSharedPtr fp = pass->getFragmentProgramParameters();
    fp->setNamedConstant("plateColour", ogre(s.plateColour));
    const double a = std::max(dot(s.centre - s.lamp, s.facing), s.lightRadius);
    fp->setNamedConstant("plateGlow", ogre(s.lightColour * (s.intensity / (a * a))) * kGlowShare);
    fp->setNamedConstant("plateHalf", Ogre::Vector2(static_cast<float>(m.halfWidth), static_cast<float>(m.halfHeight)));
    plateMaterials_.push_back(mat);

    auto* plate = scene_.createManualObject("Obscura/Signs/Plate" + std::to_string(i));
    const Ogre::Vector3 c = ogre(s.centre), r = ogre(s.right) * static_cast<float>(m.halfWidth),
                        u = ogre(s.up) * static_cast<float>(m.halfHeight), f = ogre(s.facing), back = -f * kPlateThickness;
    plate->begin(mat->getName(), Ogre::RenderOperation::OT_TRIANGLE_LIST);
    auto quad = [&](Ogre::Vector3 p0, Ogre::Vector3 p1, Ogre::Vector3 p2, Ogre::Vector3 p3, Ogre::Vector3 n, bool front) {
        const Ogre::Vector2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        const Ogre::uint32 base = static_cast<Ogre::uint32>(plate->getCurrentVertexCount());
        const Ogre::Vector3 ps[4] = {p0, p1, p2, p3};
        for (int k = 0; k < 4; ++k) {
            plate->position(ps[k]);
            plate->normal(n);
            plate->textureCoord(front ? uv[k] : Ogre::Vector2(-1, -1));
        }
        plate->triangle(base, base + 1, base + 2);
        plate->triangle(base, base + 2, base + 3);
    };
    // Counter-clockwise seen from outside each face.
    quad(c - r - u, c + r - u, c + r + u, c - r + u, f, true);
    quad(c + r - u + back, c - r - u + back, c - r + u + back, c + r + u + back, -f, false);
    quad(c - r - u + back, c + r - u + back, c + r - u, c - r - u, -ogre(s.up), false);
    quad(c - r + u, c + r + u, c + r + u + back, c - r + u + back, ogre(s.up), false);
    quad(c + r - u, c + r - u + back, c + r + u + back, c + r + u, ogre(s.right), false);
    quad(c - r - u + back, c - r - u, c - r + u, c - r + u + back, -ogre(s.right), false);
    plate->end();
    plate->setVisibilityFlags(kPlateVisibilityFlag);
    Ogre::SceneNode* node = scene_.getRootSceneNode()->createChildSceneNode();
    node->attachObject(plate);
    plates_.push_back(plate);
    nodes_.push_back(node);
}

void SignRender::updatePlate(std::size_t i) {
    const Ogre::GpuProgramParametersSharedPtr fp = plateMaterials_[i]->getTechnique(0)->getPass(0)->getFragmentProgramParameters();
    float holes[SIGN_MAX_HOLES * 4] = {};
    for (std::size_t h = 0; h < holes_[i].size() && h < SIGN_MAX_HOLES; ++h) {
        holes[h * 4 + 0] = static_cast<float>(holes_[i][h].x);
        holes[h * 4 + 1] = static_cast<float>(holes_[i][h].y);
        holes[h * 4 + 2] = static_cast<float>(holes_[i][h].radius);
    }
    fp->setNamedConstant("plateHoleCount", static_cast<float>(holes_[i].size()));
    fp->setNamedConstant("plateHoles", holes, SIGN_MAX_HOLES, 4);
}

void SignRender::update(const std::vector<SignHoles>& holes, std::uint64_t version, const Ogre::Camera& view) {
    if (version != holesVersion_) {
        holesVersion_ = version;
        for (std::size_t i = 0; i < specs_.size() && i < holes.size(); ++i) {
            holes_[i] = holes[i].holes();
            updatePlate(i);
            meshuggah_->setHoles(i, holes_[i]);
        }
    }
    // The nearest signs whose beam is in view (its box, beamBounds: a sign whose light shows
    // nowhere in the frame costs no shadow map, no surface pass and no march) and could reach the
    // camera's surroundings: by distance to the lamp, minus its range (a sign whose light cannot
    // reach within 8 m of the camera is not worth a slot).
    const Ogre::Vector3 camera = view.getDerivedPosition();
    std::vector<std::pair<float, std::size_t>> order;
    for (std::size_t i = 0; i < specs_.size(); ++i) {
        if (!view.isVisible(Ogre::AxisAlignedBox(ogre(beamLo_[i]), ogre(beamHi_[i])))) continue;
        const float d = camera.distance(ogre(specs_[i].lamp)) - static_cast<float>(specs_[i].range);
        if (d < 8.f) order.push_back({std::max(d, 0.f) + 1e-3f * static_cast<float>(i), i});
    }
    std::sort(order.begin(), order.end());
    chosen_.clear();
    for (std::size_t k = 0; k < order.size() && k < SIGN_MAX_LIGHTS; ++k) chosen_.push_back(order[k].second);
    std::sort(chosen_.begin(), chosen_.end());  // a stable slot per sign while the set stays
    if (mode_ != SignMode::Off)
        for (std::size_t k = 0; k < chosen_.size(); ++k) drawShadow(k);
    std::vector<Ogre::TexturePtr> maps;
    std::vector<Ogre::Matrix4> matrices;
    for (std::size_t k = 0; k < chosen_.size(); ++k) maps.push_back(shadows_[k].texture), matrices.push_back(shadows_[k].worldToClip);
    meshuggah_->update(mode_ == SignMode::Meshuggah, chosen_, maps, matrices, haze_);
}

void SignRender::bindSigns(Ogre::Pass& pass, frame::Uniforms& u) const {
    float centre[SIGN_MAX_LIGHTS * 3] = {}, right[SIGN_MAX_LIGHTS * 3] = {}, up[SIGN_MAX_LIGHTS * 3] = {},
          facing[SIGN_MAX_LIGHTS * 3] = {}, plate[SIGN_MAX_LIGHTS * 4] = {}, lamp[SIGN_MAX_LIGHTS * 4] = {},
          colour[SIGN_MAX_LIGHTS * 4] = {}, cone[SIGN_MAX_LIGHTS * 4] = {}, holes[SIGN_HOLE_SLOTS * 4] = {};
    float shadow[SIGN_MAX_LIGHTS * 16] = {}, maskSize[SIGN_MAX_LIGHTS * 2] = {};
    const auto put3 = [](float* out, const Vec3& v) {
        out[0] = static_cast<float>(v.x), out[1] = static_cast<float>(v.y), out[2] = static_cast<float>(v.z);
    };
    for (std::size_t k = 0; k < SIGN_MAX_LIGHTS; ++k) {
        const bool used = k < chosen_.size();
        const std::string n = std::to_string(k);
        if (auto* unit = pass.getTextureUnitState("signMask" + n)) unit->setTexture(used ? maskTextures_[chosen_[k]] : noMask_);
        if (auto* unit = pass.getTextureUnitState("signShadow" + n)) unit->setTexture(used ? shadows_[k].texture : noShadow_);
        if (!used) continue;
        const SignSpec& s = specs_[chosen_[k]];
        const SignMask& m = masks_[chosen_[k]];
        put3(centre + k * 3, s.centre);
        put3(right + k * 3, s.right);
        put3(up + k * 3, s.up);
        put3(facing + k * 3, s.facing);
        plate[k * 4 + 0] = static_cast<float>(m.halfWidth);
        plate[k * 4 + 1] = static_cast<float>(m.halfHeight);
        plate[k * 4 + 2] = static_cast<float>(holes_[chosen_[k]].size());
        plate[k * 4 + 3] = static_cast<float>(m.texel);
        maskSize[k * 2 + 0] = static_cast<float>(m.width);
        maskSize[k * 2 + 1] = static_cast<float>(m.height);
        put3(lamp + k * 4, s.lamp);
        lamp[k * 4 + 3] = static_cast<float>(s.lightRadius);
        put3(colour + k * 4, s.lightColour * s.intensity);
        colour[k * 4 + 3] = static_cast<float>(s.range);
        const double rad = s.coneDegrees * 3.14159265358979 / 180;
        cone[k * 4 + 0] = static_cast<float>(std::cos(rad));
        cone[k * 4 + 1] = static_cast<float>(std::cos(0.85 * rad));
        const auto& hs = holes_[chosen_[k]];
        for (std::size_t h = 0; h < hs.size() && h < SIGN_MAX_HOLES; ++h) {
            float* o = holes + (k * SIGN_MAX_HOLES + h) * 4;
            o[0] = static_cast<float>(hs[h].x), o[1] = static_cast<float>(hs[h].y), o[2] = static_cast<float>(hs[h].radius);
        }
        // Row-major, as OGRE uploads its own matrices (transposed into GLSL's columns).
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) shadow[k * 16 + static_cast<std::size_t>(r * 4 + c)] = shadows_[k].worldToClip[r][c];
    }
    u.set("signCount", static_cast<float>(chosen_.size()));
    u.setArray("signCentre", centre, SIGN_MAX_LIGHTS, 3);
    u.setArray("signRight", right, SIGN_MAX_LIGHTS, 3);
    u.setArray("signUp", up, SIGN_MAX_LIGHTS, 3);
    u.setArray("signFacing", facing, SIGN_MAX_LIGHTS, 3);
    u.setArray("signPlate", plate, SIGN_MAX_LIGHTS, 4);
    u.setArray("signMaskSize", maskSize, SIGN_MAX_LIGHTS, 2);
    u.setArray("signLamp", lamp, SIGN_MAX_LIGHTS, 4);
    u.setArray("signColour", colour, SIGN_MAX_LIGHTS, 4);
    u.setArray("signCone", cone, SIGN_MAX_LIGHTS, 4);
    u.setArray("signHoles", holes, SIGN_HOLE_SLOTS, 4);
    u.setArray("signShadowMatrix", shadow, SIGN_MAX_LIGHTS, 16);
}

}  // namespace obscura::signs
