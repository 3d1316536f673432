// See frame.h.
#include "frame/frame.h"

#include "frame/frame_shared.h"
#include "gbuffer_view/gbuffer_view.h"

#include <Ogre.h>
#include <OgreCompositorChain.h>
#include <OgreCompositorManager.h>

#include <algorithm>
#include <iostream>

namespace obscura::frame {

namespace {
// Pass identifiers of the frame's own quad passes (media/frame/frame.compositor).
constexpr Ogre::uint32 kLightingPass = 1, kOutputPass = 2;
// The volumetrics compositor's own passes after the march (kVolumesPass): media/frame/frame.compositor.
constexpr Ogre::uint32 kVolumeResolvePass = 31, kVolumeCopyPass = 32;
// The half-resolution pixel of each 2x2 block marched in frame n: kVolumePhase[n % FRAME_VOLUME_PHASES].
constexpr float kVolumePhase[FRAME_VOLUME_PHASES][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
const char* const kGBufferScheme = "GBuffer";
// The split G-buffer's two schemes (Obscura/Frame/GBufferSplit) and the part each compiles.
const char* const kPartSchemes[2] = {"GBufferA", "GBufferB"};
// The frame's own compositors and the stage each stands for.
struct Builtin {
    Stage stage;
    const char* compositor;
};
const Builtin kBuiltins[] = {{Stage::GBuffer, "Obscura/Frame/GBuffer"},
                             {Stage::Lighting, "Obscura/Frame/Lighting"},
                             {Stage::Output, "Obscura/Frame/Output"}};
const char* const kSplitGBuffer = "Obscura/Frame/GBufferSplit";

Ogre::TexturePtr constantTexture(const std::string& name, Ogre::PixelFormat format, const float* texel) {
    Ogre::Image image;
    image.loadDynamicImage(reinterpret_cast<Ogre::uchar*>(const_cast<float*>(texel)), 1, 1, 1, format);
    return Ogre::TextureManager::getSingleton().loadImage(name, Ogre::RGN_DEFAULT, image, Ogre::TEX_TYPE_2D, 0);
}
}  // namespace

const char* stageName(Stage s) {
    switch (s) {
        case Stage::GBuffer: return "G-buffer";
        case Stage::Decals: return "decals";
        case Stage::AO: return "AO";
        case Stage::Lighting: return "lighting";
        case Stage::Volumetrics: return "volumetrics";
        case Stage::Output: return "output";
    }
    return "?";
}

bool Gpu::renderTargetFormat(Ogre::PixelFormat f, bool volume) const {
    const std::string name = (volume ? "3d:" : "") + Ogre::PixelUtil::getFormatName(f);
    if (std::find(unsupportedFormats.begin(), unsupportedFormats.end(), name) != unsupportedFormats.end()) return false;
    return Ogre::TextureManager::getSingleton().isFormatSupported(volume ? Ogre::TEX_TYPE_3D : Ogre::TEX_TYPE_2D, f,
                                                                  Ogre::TU_RENDERTARGET);
}

void setViewRay(Uniforms& u, const FrameContext& ctx) {
    const Ogre::Matrix4& proj = ctx.camera->getProjectionMatrix();
    u.set("projScale", Ogre::Vector2(proj[0][0], proj[1][1]));
    u.set("flipY", ctx.flipY ? 1.0f : 0.0f);
    u.set("inverseView", ctx.camera->getViewMatrix().inverse());
}

bool Uniforms::check(const char* name) {
    if (!missing_) return true;
    if (!params_._findNamedConstantDefinition(name)) missing_->push_back(name);
    return false;
}

// One compositor of the chain: the frame's own (no techniques) or a technique's. Techniques that
// name the same compositor share it (the volumetric pass: smoke and sign shafts are marched
// together, one transmittance), each binding its own uniforms and textures into its passes.
struct Frame::Entry {
    Stage stage;
    std::string compositor;
    std::vector<Technique*> techniques;
    Ogre::CompositorInstance* instance = nullptr;
    std::unique_ptr<Binder> binder;
    std::vector<std::string> missing;  // "material: uniform" its programs lack (found at setup)
};

class Frame::Binder : public Ogre::CompositorInstance::Listener {
public:
    Binder(Frame& frame, Entry& entry) : frame_(frame), entry_(entry) {}
    void notifyMaterialSetup(Ogre::uint32 passId, Ogre::MaterialPtr& mat) override { frame_.setupPass(entry_, passId, *mat); }
    void notifyMaterialRender(Ogre::uint32 passId, Ogre::MaterialPtr& mat) override { frame_.renderPass(entry_, passId, *mat); }

private:
    Frame& frame_;
    Entry& entry_;
};

Frame::Frame(Ogre::Viewport& viewport, Ogre::Camera& camera, FrameSettings settings)
    : viewport_(viewport), camera_(camera), settings_(std::move(settings)) {
    const Ogre::RenderSystemCapabilities* caps = Ogre::Root::getSingleton().getRenderSystem()->getCapabilities();
    gpu_.renderTargets = caps ? caps->getNumMultiRenderTargets() : 1;
    if (settings_.maxRenderTargets > 0) gpu_.renderTargets = std::min(gpu_.renderTargets, settings_.maxRenderTargets);
    gpu_.unsupportedFormats = settings_.unsupportedFormats;
    // The frame itself cannot be turned off: without these there is no picture to draw into.
    const int splitTargets = std::max(FRAME_GBUFFER_SPLIT, FRAME_GBUFFER_TARGETS - FRAME_GBUFFER_SPLIT);
    if (gpu_.renderTargets < splitTargets)
        throw std::runtime_error("frame: the G-buffer needs " + std::to_string(splitTargets) + " simultaneous render targets (" +
                                 std::to_string(FRAME_GBUFFER_TARGETS) + " to draw the scene once) and this GPU has " +
                                 std::to_string(gpu_.renderTargets));
    split_ = gpu_.renderTargets < FRAME_GBUFFER_TARGETS;
    if (split_)
        std::cerr << "obscura: frame: the G-buffer is drawn in two passes (this GPU has " << gpu_.renderTargets
                  << " simultaneous render targets, one pass needs " << FRAME_GBUFFER_TARGETS << ")\n";
    for (Ogre::PixelFormat f : {Ogre::PF_A8B8G8R8, Ogre::PF_FLOAT32_R, Ogre::PF_FLOAT16_RGBA, Ogre::PF_R11G11B10_FLOAT})
        if (!gpu_.renderTargetFormat(f))
            throw std::runtime_error("frame: the G-buffer needs render targets in " + Ogre::PixelUtil::getFormatName(f) +
                                     ", which this GPU lacks");

    auto& mm = Ogre::MaterialManager::getSingleton();
    gbufferFallback_ = mm.getByName("Obscura/Level/GBufferFallback");  // a light-grey level surface
    if (!gbufferFallback_) throw std::runtime_error("material Obscura/Level/GBufferFallback (media/materials/level.material) is missing");
    gbufferFallback_->load();
    mm.addListener(this, kGBufferScheme);
    for (const char* scheme : kPartSchemes) mm.addListener(this, scheme);

    const float open[2] = {1, 0};         // AO 1 (nothing occluded), depth 0
    const float clear[4] = {0, 0, 0, 1};  // no light, transmittance 1
    noAo_ = constantTexture("Obscura/Frame/NoAO", Ogre::PF_FLOAT32_GR, open);
    noVolume_ = constantTexture("Obscura/Frame/NoVolume", Ogre::PF_FLOAT32_RGBA, clear);
    const float none[4] = {0, 0, 0, 0};  // no decal: nothing over the albedo
    noDecals_ = constantTexture("Obscura/Frame/NoDecals", Ogre::PF_FLOAT32_RGBA, none);
    context_.camera = &camera_;
    // The frame's own debug passes.
    own_.push_back(std::make_unique<gbuffer_view::GBufferView>());
    for (auto& t : own_) add(*t);
}

Frame::~Frame() {
    removeAll();
    auto& mm = Ogre::MaterialManager::getSingleton();
    mm.removeListener(this, kGBufferScheme);
    for (const char* scheme : kPartSchemes) mm.removeListener(this, scheme);
    gbufferFallback_.reset();
    published_.clear();
    Ogre::TextureManager::getSingleton().remove(noAo_);
    Ogre::TextureManager::getSingleton().remove(noVolume_);
    Ogre::TextureManager::getSingleton().remove(noDecals_);
}

void Frame::add(Technique& technique) {
    techniques_.push_back(&technique);
    builtKey_.clear();
}

std::string Frame::key() const {
    std::string k;
    for (const Technique* t : techniques_) k += t->compositor() + "|" + t->configuration() + ";";
    return k;
}

std::string Frame::offReason(const Technique& technique) const {
    auto it = off_.find(&technique);
    return it != off_.end() && it->second.first == technique.compositor() + "|" + technique.configuration()
               ? it->second.second
               : std::string();
}

void Frame::turnOff(const Technique& t, const std::string& reason) {
    const std::string line = std::string("frame: the ") + stageName(t.stage()) + " stage (" + t.folder() + ") is off: " + reason;
    off_[&t] = {t.compositor() + "|" + t.configuration(), line};
    std::cerr << "obscura: " << line << "\n";
    Ogre::LogManager::getSingleton().logError(line);
}

// The chain in stage order: the frame's own compositors and every technique that runs now.
std::vector<std::unique_ptr<Frame::Entry>> Frame::plan() const {
    std::vector<std::unique_ptr<Entry>> p;
    auto entry = [&p](Stage stage, std::string compositor, std::vector<Technique*> techniques) {
        p.push_back(std::make_unique<Entry>());
        p.back()->stage = stage;
        p.back()->compositor = std::move(compositor);
        p.back()->techniques = std::move(techniques);
    };
    for (const Builtin& b : kBuiltins) entry(b.stage, split_ && b.stage == Stage::GBuffer ? kSplitGBuffer : b.compositor, {});
    for (Technique* t : techniques_) {
        if (t->compositor().empty() || !offReason(*t).empty()) continue;
        auto shared = std::find_if(p.begin(), p.end(), [&](const auto& e) { return e->compositor == t->compositor(); });
        if (shared != p.end() && !(*shared)->techniques.empty()) (*shared)->techniques.push_back(t);
        else entry(t->stage(), t->compositor(), {t});
    }
    // Stable: the frame's own pass of a stage comes before techniques of that stage, techniques in
    // the order they were added.
    std::stable_sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a->stage < b->stage; });
    return p;
}

std::vector<std::string> Frame::views() const {
    std::vector<std::string> v = {"scene", "ao"};
    for (const Technique* t : techniques_)
        for (const auto& name : t->views()) v.push_back(name);
    return v;
}

void Frame::setView(const std::string& view) {
    const auto all = views();
    view_ = std::find(all.begin(), all.end(), view) != all.end() ? view : "scene";
    for (Technique* t : techniques_) {
        const auto own = t->views();
        t->showView(std::find(own.begin(), own.end(), view_) != own.end() ? view_ : std::string());
    }
}

void Frame::update(float time) {
    context_.time = time;
    if (key() != builtKey_) rebuild();
}

void Frame::removeAll() {
    auto& cm = Ogre::CompositorManager::getSingleton();
    for (auto& e : chain_)
        if (e->instance) {
            e->instance->removeListener(e->binder.get());
            cm.removeCompositor(&viewport_, e->compositor);
        }
    chain_.clear();
    builtKey_.clear();
}

bool Frame::instance(Entry& e) {
    auto& cm = Ogre::CompositorManager::getSingleton();
    Ogre::CompositorPtr comp = cm.getByName(e.compositor, Ogre::RGN_DEFAULT);
    if (!comp) {
        if (e.techniques.empty()) throw std::runtime_error("frame: compositor " + e.compositor + " (media/frame/frame.compositor) is missing");
        for (Technique* t : e.techniques) turnOff(*t, "its compositor " + e.compositor + " is not defined");
        return false;
    }
    bool ready = true;
    for (Technique* t : e.techniques) {
        const std::string missing = t->missingFeature(gpu_);
        if (!missing.empty()) turnOff(*t, "it needs " + missing);
        ready = ready && missing.empty();
    }
    if (!ready) return false;
    if (!e.techniques.empty()) {
        comp->load();
        for (size_t i = 0; i < comp->getNumTechniques(); ++i)
            for (Technique* t : e.techniques) t->configure(*comp->getTechnique(i));
    }
    e.instance = cm.addCompositor(&viewport_, e.compositor);
    if (!e.instance || !e.instance->getTechnique()) {
        const std::string why = "compositor " + e.compositor + " cannot run here (see the OGRE log)";
        if (e.instance) cm.removeCompositor(&viewport_, e.compositor);
        e.instance = nullptr;
        if (e.techniques.empty()) throw std::runtime_error("frame: " + why);
        for (Technique* t : e.techniques) turnOff(*t, why);
        return false;
    }
    e.binder = std::make_unique<Binder>(*this, e);
    e.instance->addListener(e.binder.get());
    e.instance->setEnabled(true);
    return true;
}

// What later passes read by texture-unit name: the G-buffer, the light, and each technique's output.
void Frame::publish() {
    published_.clear();
    published_["aoMap"] = noAo_;
    published_["volumeMap"] = noVolume_;
    published_["decalAlbedo"] = noDecals_;
    published_["decalNormal"] = noDecals_;  // coverage 0: the G-buffer's normal as it is
    for (auto& e : chain_) {
        if (e->stage == Stage::GBuffer && e->techniques.empty()) {
            // One 5-target texture, or the split's 2- and 3-target ones (frame.compositor).
            auto target = [&](int slot) {
                if (!split_) return e->instance->getTextureInstance("gbuffer", slot);
                if (slot < FRAME_GBUFFER_SPLIT) return e->instance->getTextureInstance("gbufferA", slot);
                return e->instance->getTextureInstance("gbufferB", slot - FRAME_GBUFFER_SPLIT);
            };
            published_["gbufferAlbedo"] = target(FRAME_GBUFFER_ALBEDO);
            published_["gbufferNormal"] = target(FRAME_GBUFFER_NORMAL);
            published_["gbufferDepth"] = target(FRAME_GBUFFER_DEPTH);
            published_["gbufferLight"] = target(FRAME_GBUFFER_LIGHT);
            published_["gbufferAmbient"] = target(FRAME_GBUFFER_AMBIENT);
            context_.flipY = e->instance->getRenderTarget(split_ ? "gbufferA" : "gbuffer")->requiresTextureFlipping();
        } else if (e->stage == Stage::Lighting && e->techniques.empty()) {
            published_["litMap"] = e->instance->getTextureInstance("lit", 0);
        } else {
            for (const Technique* t : e->techniques)
                for (const Technique::Output& out : t->outputs())
                    published_[out.unit] = e->instance->getTextureInstance(out.texture, out.mrt);
        }
    }
}

Ogre::TexturePtr Frame::published(const std::string& unit, bool* standIn) const {
    const auto it = published_.find(unit);
    if (it == published_.end()) return {};
    if (standIn) *standIn = it->second == noAo_ || it->second == noVolume_ || it->second == noDecals_;
    return it->second;
}

void Frame::addSceneMaterial(const Ogre::MaterialPtr& material) {
    sceneMaterials_.push_back(material);
    if (!published_.empty()) bindSceneMaterial(*material);
}

void Frame::bindSceneMaterial(Ogre::Material& material) {
    for (Ogre::Technique* t : material.getTechniques())
        for (Ogre::Pass* pass : t->getPasses())
            for (unsigned short i = 0; i < pass->getNumTextureUnitStates(); ++i) {
                Ogre::TextureUnitState* unit = pass->getTextureUnitState(i);
                if (auto it = published_.find(unit->getName()); it != published_.end()) unit->setTexture(it->second);
            }
}

void Frame::rebuild() {
    for (;;) {
        removeAll();
        const std::string k = key();
        chain_ = plan();
        bool complete = true;
        for (auto& e : chain_) complete = instance(*e) && complete;
        if (!complete) continue;  // a technique was turned off: plan again without it
        publish();
        for (const auto& m : sceneMaterials_) bindSceneMaterial(*m);
        // Compile now, outside any render: every quad pass is set up (textures bound, uniform names
        // checked) here rather than inside the first frame.
        Ogre::CompositorManager::getSingleton().getCompositorChain(&viewport_)->_compile();
        bool checked = true;
        for (auto& e : chain_) {
            if (e->missing.empty()) continue;
            std::string list;
            for (const auto& m : e->missing) list += (list.empty() ? "" : ", ") + m;
            if (e->techniques.empty()) throw std::runtime_error("frame: " + e->compositor + ": the program lacks uniforms " + list);
            for (Technique* t : e->techniques) turnOff(*t, "its program does not declare the uniform(s) the C++ sets: " + list);
            checked = false;
        }
        if (!checked) continue;
        builtKey_ = k;
        volumeFrames_ = 0;  // a new chain's volume buffers hold nothing yet
        return;
    }
}

void Frame::setupPass(Entry& e, Ogre::uint32 passId, Ogre::Material& mat) {
    Ogre::Pass* pass = mat.getTechnique(0)->getPass(0);
    for (unsigned short i = 0; i < pass->getNumTextureUnitStates(); ++i) {
        Ogre::TextureUnitState* unit = pass->getTextureUnitState(i);
        if (auto it = published_.find(unit->getName()); it != published_.end()) unit->setTexture(it->second);
    }
    for (Technique* t : e.techniques) t->setup(passId, *pass);
    if (!pass->hasFragmentProgram()) return;
    mat.load();
    std::vector<std::string> missing;
    Uniforms check(*pass->getFragmentProgramParameters(), &missing);
    bind(e, passId, *pass, check);
    // The compositor's copy is named "c<N>/" + the script's name: say the script's name.
    std::string name = mat.getName();
    if (name.size() > 1 && name[0] == 'c' && std::isdigit(static_cast<unsigned char>(name[1])) && name.find('/') != std::string::npos)
        name = name.substr(name.find('/') + 1);
    for (const auto& m : missing) e.missing.push_back("material " + name + " has no parameter '" + m + "'");
}

void Frame::renderPass(Entry& e, Ogre::uint32 passId, Ogre::Material& mat) {
    Ogre::Pass* pass = mat.getBestTechnique()->getPass(0);
    if (!pass->hasFragmentProgram()) return;
    Uniforms set(*pass->getFragmentProgramParameters(), nullptr);
    bind(e, passId, *pass, set);
}

int Frame::settleVolumes() {
    const bool marched = std::any_of(chain_.begin(), chain_.end(), [](const auto& e) { return e->compositor == kVolumesCompositor; });
    if (!marched) return 0;
    volumeFrames_ -= volumeFrames_ % FRAME_VOLUME_PHASES;  // 0 stays 0: a new chain's first frame has no history
    return FRAME_VOLUME_PHASES;
}

void Frame::setAmbientAreas(std::vector<AmbientBox> areas) {
    if (areas.size() > FRAME_MAX_AMBIENT_AREAS) areas.resize(FRAME_MAX_AMBIENT_AREAS);
    ambientAreas_ = std::move(areas);
}

void Frame::bind(Entry& e, Ogre::uint32 passId, Ogre::Pass& pass, Uniforms& u) {
    const float* phase = kVolumePhase[volumeFrames_ % FRAME_VOLUME_PHASES];
    if (passId == kVolumesPass) {  // for whichever techniques march in it
        setViewRay(u, context_);
        u.set("volumeMarchPhase", Ogre::Vector2(phase[0], phase[1]));
    } else if (passId == kVolumeResolvePass) {
        setViewRay(u, context_);
        u.set("volumeMarchPhase", Ogre::Vector2(phase[0], phase[1]));
        u.set("volumeHistoryValid", volumeFrames_ > 0 ? 1.0f : 0.0f);
        u.set("previousView", volumeLastView_);
        if (!u.checking()) {  // this frame's march and resolve are bound: the next frame's turn
            volumeLastView_ = camera_.getViewMatrix();
            ++volumeFrames_;
        }
        return;
    } else if (passId == kVolumeCopyPass) {
        return;
    }
    for (Technique* t : e.techniques) t->bind(passId, pass, u, context_);
    if (!e.techniques.empty()) return;
    if (passId == kLightingPass) {
        u.set("aoPresent", published_["aoMap"] != noAo_ ? 1.0f : 0.0f);
        setViewRay(u, context_);  // the ambient areas are tested at each pixel's world position
        float mins[FRAME_MAX_AMBIENT_AREAS * 4] = {}, maxs[FRAME_MAX_AMBIENT_AREAS * 4] = {};
        for (std::size_t i = 0; i < ambientAreas_.size(); ++i) {
            const AmbientBox& a = ambientAreas_[i];
            for (int c = 0; c < 3; ++c) mins[i * 4 + c] = a.min[c], maxs[i * 4 + c] = a.max[c];
            mins[i * 4 + 3] = a.scale;
            maxs[i * 4 + 3] = a.blend;
        }
        u.set("ambientAreaCount", static_cast<float>(ambientAreas_.size()));
        u.setArray("ambientAreaMin", mins, FRAME_MAX_AMBIENT_AREAS, 4);
        u.setArray("ambientAreaMax", maxs, FRAME_MAX_AMBIENT_AREAS, 4);
        u.set("exposure", settings_.exposure);  // undoes the tone map for the sky
        u.set("view", camera_.getViewMatrix(true));  // the G-buffer's view normals back to the world (decals' normals)
    } else if (passId == kOutputPass) {
        u.set("exposure", settings_.exposure);
        u.set("view", view_ == "ao" ? 1.0f : 0.0f);
        u.set("aoPresent", published_["aoMap"] != noAo_ ? 1.0f : 0.0f);
        u.set("volumePresent", published_["volumeMap"] != noVolume_ ? 1.0f : 0.0f);
    }
}

// The GBuffer technique of `material` (or the fallback's): getTechnique, not getBestTechnique,
// which would ask this listener again.
static Ogre::Technique* gbufferTechnique(Ogre::Material& material, Ogre::Material& fallback) {
    for (Ogre::Technique* t : material.getTechniques())
        if (t->getSchemeName() == kGBufferScheme) return t;
    return fallback.getTechnique(0);
}

Ogre::Technique* Frame::handleSchemeNotFound(unsigned short, const Ogre::String& schemeName, Ogre::Material* material,
                                             unsigned short, const Ogre::Renderable*) {
    if (schemeName == kGBufferScheme) return gbufferFallback_->getTechnique(0);
    const int part = schemeName == kPartSchemes[0] ? 0 : schemeName == kPartSchemes[1] ? 1 : -1;
    if (part < 0 || !material) return nullptr;
    // Both halves join the material itself, so OGRE finds them from now on without asking.
    Ogre::Technique& gbuffer = *gbufferTechnique(*material, *gbufferFallback_);
    Ogre::Technique* halves[2] = {addPart(*material, gbuffer, 0), addPart(*material, gbuffer, 1)};
    material->compile();
    return halves[part];
}

// A copy of a GBuffer technique that writes one half of the G-buffer, added to `material`: its
// fragment program, when it writes the G-buffer (includes gbuffer_out.glsl), compiled again with
// FRAME_GBUFFER_PART; anything else (the shadow caster's) as it is.
Ogre::Technique* Frame::addPart(Ogre::Material& material, const Ogre::Technique& gbuffer, int part) {
    Ogre::Technique* t = material.createTechnique();
    *t = gbuffer;
    t->setSchemeName(kPartSchemes[part]);
    for (Ogre::Pass* pass : t->getPasses()) {
        if (!pass->hasFragmentProgram()) continue;
        const Ogre::GpuProgramPtr& fp = pass->getFragmentProgram();
        // (OGRE inlines #include at load: look for what gbuffer_out.glsl defines.)
        if (fp->getSource().find("void writeGBuffer(") == std::string::npos) continue;
        const std::string name = fp->getName() + "/" + kPartSchemes[part];
        auto& gm = Ogre::HighLevelGpuProgramManager::getSingleton();
        Ogre::HighLevelGpuProgramPtr variant = gm.getByName(name, fp->getGroup());
        if (!variant) {
            variant = gm.createProgram(name, fp->getGroup(), "glsl", Ogre::GPT_FRAGMENT_PROGRAM);
            variant->setSourceFile(fp->getSourceFile());
            // The program's own defines kept (the level's LEVEL_BAKED variant), the part's added.
            const std::string own = fp->getParameter("preprocessor_defines");
            variant->setParameter("preprocessor_defines", (own.empty() ? "" : own + ",") + "FRAME_GBUFFER_PART=" + std::to_string(part));
            variant->load();
            Ogre::GpuProgramParametersSharedPtr defaults = variant->getDefaultParameters();
            defaults->copyMatchingNamedConstantsFrom(*fp->getDefaultParameters());
            for (const auto& shared : fp->getDefaultParameters()->getSharedParameters())
                defaults->addSharedParameters(shared.getName());
        }
        const Ogre::GpuProgramParametersSharedPtr old = pass->getFragmentProgramParameters();
        pass->setFragmentProgram(name);
        pass->getFragmentProgramParameters()->copyMatchingNamedConstantsFrom(*old);
    }
    return t;
}

}  // namespace obscura::frame
