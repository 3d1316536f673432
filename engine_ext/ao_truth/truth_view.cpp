// See truth_view.h.
#include "ao_truth/truth_view.h"

#include <OgrePass.h>
#include <OgreTextureManager.h>
#include <OgreTextureUnitState.h>
#include <OgreHardwarePixelBuffer.h>

namespace obscura::ao_truth {

namespace {
constexpr const char* kPictureName = "Obscura/AoTruth/Picture";
}

TruthView::TruthView() { upload(1, 1, {0, 0, 0, 255}); }

TruthView::~TruthView() {
    if (picture_) Ogre::TextureManager::getSingleton().remove(picture_);
}

std::string TruthView::configuration() const { return std::to_string(width_) + "x" + std::to_string(height_); }

void TruthView::setup(Ogre::uint32, Ogre::Pass& pass) {
    if (Ogre::TextureUnitState* unit = pass.getTextureUnitState("truthMap")) unit->setTexture(picture_);
}

void TruthView::bind(Ogre::uint32, Ogre::Pass&, frame::Uniforms& u, const frame::FrameContext&) {
    // 1: the uploaded picture; 2: the AO buffer (shaders/ao_truth/truth_view.frag).
    u.set("truthShow", show_ == Show::Mode ? 2.0f : 1.0f);
}

void TruthView::upload(int width, int height, const std::vector<std::uint8_t>& rgba) {
    auto& tm = Ogre::TextureManager::getSingleton();
    if (!picture_ || width != width_ || height != height_) {
        if (picture_) tm.remove(picture_);
        picture_ = tm.createManual(kPictureName, Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, static_cast<Ogre::uint>(width),
                                   static_cast<Ogre::uint>(height), 0, Ogre::PF_BYTE_RGBA, Ogre::TU_DYNAMIC_WRITE_ONLY);
        width_ = width;
        height_ = height;  // configuration() changes: the frame rebuilds and setup() binds the new one
    }
    const Ogre::PixelBox box(static_cast<Ogre::uint32>(width), static_cast<Ogre::uint32>(height), 1, Ogre::PF_BYTE_RGBA,
                             const_cast<std::uint8_t*>(rgba.data()));
    picture_->getBuffer()->blitFromMemory(box);
}

}  // namespace obscura::ao_truth
