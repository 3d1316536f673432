// See pass_order.h.
#include "render/pass_order.h"

#include "render/pass_order_key.h"

#include <OgreMaterial.h>
#include <OgrePass.h>
#include <OgreTechnique.h>

namespace obscura::render {

namespace {
struct NamedPassOrder : Ogre::Pass::HashFunc {
    Ogre::uint32 operator()(const Ogre::Pass* p) const override {
        const Ogre::Technique* t = p->getParent();
        const Ogre::Material* m = t ? t->getParent() : nullptr;
        return passOrderKey(m ? m->getName() : "", t ? t->getSchemeName() : "", t ? t->getName() : "", p->getIndex());
    }
};
}  // namespace

void installNamedPassOrder() {
    static NamedPassOrder order;  // OGRE keeps the pointer for the process's life
    Ogre::Pass::setHashFunction(&order);
}

}  // namespace obscura::render
