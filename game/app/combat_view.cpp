// See combat_view.h.
#include "app/combat_view.h"

#include "frame/frame.h"
#include "render/level_materials.h"
#include "render/ogre_convert.h"
#include "render/prop_view.h"

#include <Ogre.h>
#include <OgreBillboardSet.h>

#include <algorithm>

namespace obscura {

namespace {
constexpr int kSparksPerImpact = 7;          // enough to read as a burst, few enough to stay cheap
constexpr double kGravity = 9.81;            // sparks fall like anything else
const Ogre::Vector3 kMuzzle(0.14f, -0.12f, -0.75f);  // camera space: down and right of the eye, where a rifle's muzzle is
}  // namespace

CombatView::CombatView(Ogre::SceneManager& scene, render::LevelMaterials& materials, Ogre::SceneNode& cameraNode,
                       const TickDurations& durations)
    : scene_(scene), durations_(durations), materials_(materials) {
    flash_ = scene_.createBillboardSet(4);
    flash_->setMaterialName("Obscura/Effects/Glow");
    flash_->setDefaultDimensions(0.35f, 0.35f);
    flash_->setCastShadows(false);
    flash_->setRenderQueueGroup(frame::kEffectsQueue);  // drawn into the HDR light after lighting
    flashNode_ = cameraNode.createChildSceneNode(kMuzzle);
    flashNode_->attachObject(flash_);
    flashNode_->setVisible(false);

    sparks_ = scene_.createBillboardSet(64);
    sparks_->setMaterialName("Obscura/Effects/Glow");
    sparks_->setDefaultDimensions(0.06f, 0.06f);
    sparks_->setCastShadows(false);
    sparks_->setRenderQueueGroup(frame::kEffectsQueue);
    scene_.getRootSceneNode()->attachObject(sparks_);
}

CombatView::~CombatView() {
    for (auto& t : targets_) {
        scene_.destroyEntity(t.board);
        scene_.destroyEntity(t.post);
        scene_.destroySceneNode(t.pivot);
        scene_.destroySceneNode(t.base);
    }
    scene_.destroyBillboardSet(sparks_);
    scene_.destroyBillboardSet(flash_);
    scene_.destroySceneNode(flashNode_);
}

void CombatView::onTick(const std::vector<sim::SimEvent>& events) {
    if (flashTicks_ > 0) --flashTicks_;
    const double dt = durations_.tickSeconds;
    for (auto& s : live_) {
        s.velocity.y -= kGravity * dt;
        s.position += s.velocity * dt;
        --s.ticksLeft;
    }
    live_.erase(std::remove_if(live_.begin(), live_.end(), [](const Spark& s) { return s.ticksLeft <= 0; }), live_.end());

    for (const auto& e : events) {
        if (e.type == sim::SimEventType::Shot) {
            flashTicks_ = durations_.muzzleFlashTicks;
            flash_->clear();
            // Two overlapping glows of random size and brightness: no two flashes alike.
            flash_->createBillboard(Ogre::Vector3::ZERO, Ogre::ColourValue(1.0f, 0.75f, 0.4f, static_cast<float>(rng_.uniform(0.7, 1.0))))
                ->setDimensions(static_cast<float>(rng_.uniform(0.25, 0.4)), static_cast<float>(rng_.uniform(0.25, 0.4)));
            flash_->createBillboard(Ogre::Vector3(0, 0, -0.08f), Ogre::ColourValue(1.0f, 0.9f, 0.6f, 0.8f))
                ->setDimensions(0.12f, 0.12f);
        } else if (e.type == sim::SimEventType::Impact) {
            // Sparks leave the surface in a cone about its normal (and a little along the shot).
            for (int i = 0; i < kSparksPerImpact; ++i) {
                const Vec3 random{rng_.uniform(-1, 1), rng_.uniform(-1, 1), rng_.uniform(-1, 1)};
                Vec3 dir = normalize(e.normal * 1.2 + random * 0.8 - e.direction * 0.3);
                live_.push_back({e.position + e.normal * 0.02, dir * rng_.uniform(2.0, 5.0), durations_.sparkTicks, durations_.sparkTicks});
            }
        }
    }
    flashNode_->setVisible(flashTicks_ > 0);
    rebuildBillboards();
}

void CombatView::rebuildBillboards() {
    sparks_->clear();
    for (const auto& s : live_) {
        const float life = static_cast<float>(s.ticksLeft) / static_cast<float>(s.lifetime);
        sparks_->createBillboard(render::toOgre(s.position), Ogre::ColourValue(1.0f, 0.7f, 0.3f, life));
    }
}

void CombatView::update(const std::vector<sim::TargetState>& targets) {
    while (targets_.size() < targets.size()) {
        TargetNodes t;
        t.base = scene_.getRootSceneNode()->createChildSceneNode();
        t.pivot = t.base->createChildSceneNode();
        t.board = scene_.createEntity(render::unitMesh(render::PropPose::Shape::Box));
        t.board->setMaterialName(materials_.resolve("target"));
        t.post = scene_.createEntity(render::unitMesh(render::PropPose::Shape::Box));
        t.post->setMaterialName(materials_.resolve("metal"));
        auto* boardNode = t.pivot->createChildSceneNode();
        boardNode->attachObject(t.board);
        auto* postNode = t.pivot->createChildSceneNode();
        postNode->attachObject(t.post);
        targets_.push_back(t);
    }
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        auto& t = targets_[i];
        const bool used = i < targets.size();
        t.base->setVisible(used);
        if (!used) continue;
        const auto& s = targets[i];
        t.base->setPosition(render::toOgre(s.position));
        t.base->setOrientation(Ogre::Quaternion(Ogre::Radian(static_cast<float>(s.yaw)), Ogre::Vector3::UNIT_Y));
        // The board faces -Z at yaw 0 (the level's convention). Down = fallen backwards, top towards
        // +Z, away from the shooter it faces, turning about its base.
        t.pivot->setOrientation(Ogre::Quaternion(Ogre::Degree(static_cast<float>(90.0 * (1.0 - s.raise))), Ogre::Vector3::UNIT_X));
        // A square board at the top of the target's height, on a thin post.
        const auto w = static_cast<float>(s.width), h = static_cast<float>(s.height);
        const float post = std::max(h - w, 0.05f);
        auto* boardNode = static_cast<Ogre::SceneNode*>(t.board->getParentNode());
        boardNode->setPosition(0, post + w * 0.5f, 0);
        boardNode->setScale(w * 0.5f, w * 0.5f, 0.02f);
        auto* postNode = static_cast<Ogre::SceneNode*>(t.post->getParentNode());
        postNode->setPosition(0, post * 0.5f, 0.03f);  // behind the board
        postNode->setScale(0.03f, post * 0.5f, 0.03f);
    }
}

}  // namespace obscura
