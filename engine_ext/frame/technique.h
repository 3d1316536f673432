// The small interface through which a technique (engine_ext/<technique>) plugs its pass into the
// frame (frame.h). The frame knows the order of the stages, and each technique knows only its own
// compositor (media/<technique>/), its own textures and its own uniforms.
#pragma once

#include <OgreGpuProgramParams.h>
#include <OgrePixelFormat.h>
#include <OgrePrerequisites.h>

#include <string>
#include <vector>

namespace Ogre {
class CompositionTechnique;
}

namespace obscura::frame {

// The frame's stages, in the order they run (media/frame/frame.compositor says the same).
enum class Stage { GBuffer, Decals, AO, Lighting, Volumetrics, Output };
const char* stageName(Stage s);

// The volumetric pass (media/frame/frame.compositor, Obscura/Frame/Volumes): every technique of
// the volumetrics stage returns this compositor and binds into this one pass, so all participating
// media are marched together with one transmittance (shaders/frame/volumes.frag). The frame sets
// the camera's uniforms there (projScale, flipY, inverseView) and the frame's volumeMarchPhase (which
// quarter of the pixels is marched: shaders/frame/frame_shared.h); its resolve and history passes
// are the frame's own.
constexpr const char* kVolumesCompositor = "Obscura/Frame/Volumes";
constexpr Ogre::uint32 kVolumesPass = 30;

// What every pass may know of the frame being drawn.
struct FrameContext {
    const Ogre::Camera* camera = nullptr;
    bool flipY = false;  // the frame's buffers are render textures stored upside down
    float time = 0;      // game seconds (noise that drifts)
};

// What the GPU offers, as the frame sees it (debug settings may take features away).
struct Gpu {
    int renderTargets = 0;  // simultaneous render targets
    std::vector<std::string> unsupportedFormats;  // render-target formats pretended missing
    bool renderTargetFormat(Ogre::PixelFormat f, bool volume = false) const;
};

// Uniform setter with the load-time check: the frame first runs every bind() against a checking
// Uniforms that records each name the program does not declare (the material named in the
// message), then runs it every frame against the real parameters, where nothing can be missing.
class Uniforms {
public:
    Uniforms(Ogre::GpuProgramParameters& params, std::vector<std::string>* missing)
        : params_(params), missing_(missing) {}
    template <class T>
    void set(const char* name, const T& value) {
        if (check(name)) params_.setNamedConstant(name, value);
    }
    void setArray(const char* name, const float* values, std::size_t count, std::size_t multiple) {
        if (check(name)) params_.setNamedConstant(name, values, count, multiple);
    }
    // The load-time check, not a frame: a bind() must not advance any state then.
    bool checking() const { return missing_ != nullptr; }

private:
    bool check(const char* name);
    Ogre::GpuProgramParameters& params_;
    std::vector<std::string>* missing_;
};

// The camera a full-screen pass rebuilds each pixel's view ray with (shaders/frame/view_ray.glsl):
// projScale, flipY, inverseView.
void setViewRay(Uniforms& u, const FrameContext& ctx);

class Technique {
public:
    virtual ~Technique() = default;
    // Where it lives, for messages: "engine_ext/ssao".
    virtual std::string folder() const = 0;
    virtual Stage stage() const = 0;
    // The compositor (media/<technique>/) for the current configuration; empty: not in the frame
    // now (AO off, no smoke). A change of this or of configuration() rebuilds the chain.
    virtual std::string compositor() const = 0;
    virtual std::string configuration() const { return {}; }
    // What it needs that `gpu` lacks, in words ("render targets in PF_FLOAT32_GR"); empty if none.
    virtual std::string missingFeature(const Gpu&) const { return {}; }
    // Before its compositor is instanced: sizes of its buffers.
    virtual void configure(Ogre::CompositionTechnique&) const {}
    // When one of its quad passes is set up: its own textures.
    virtual void setup(Ogre::uint32 /*passId*/, Ogre::Pass&) {}
    // Every frame before one of its passes renders (and once at setup, checking the names).
    virtual void bind(Ogre::uint32 passId, Ogre::Pass&, Uniforms&, const FrameContext&) = 0;
    // Its textures that later passes read, and the texture-unit names they read them by (`mrt`:
    // which of a multiple-render-target texture's surfaces).
    struct Output {
        std::string texture, unit;
        std::size_t mrt = 0;
    };
    virtual std::vector<Output> outputs() const { return {}; }
    // Debug views it can show instead of the picture (Frame::views), and the one to show now
    // ("" for none): a technique of the output stage then draws over the frame's output.
    virtual std::vector<std::string> views() const { return {}; }
    virtual void showView(const std::string& /*view*/) {}
};

}  // namespace obscura::frame
