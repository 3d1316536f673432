#include "smoke_obstacles.h"

#include <cmath>

namespace obscura {

std::vector<smoke::MovingObstacle> smokeObstacles(const sim::Simulation& sim) {
    using Shape = smoke::MovingObstacle::Shape;
    std::vector<smoke::MovingObstacle> out;
    const sim::PlayerState& player = sim.player();
    smoke::MovingObstacle body;
    body.shape = Shape::Box;
    body.halfExtents = {0.35, player.height * 0.5, 0.35};
    body.centre = player.feet + Vec3{0, player.height * 0.5, 0};
    body.velocity = player.velocity;
    out.push_back(body);
    for (const auto& b : sim.bodyPoses()) {
        // |R| h: the world box of a box (or cylinder: radius, half height, radius) turned by q.
        const double x = b.qx, y = b.qy, z = b.qz, w = b.qw;
        const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                                {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                                {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
        const double h[3] = {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
        double e[3];
        for (int i = 0; i < 3; ++i) e[i] = std::fabs(r[i][0]) * h[0] + std::fabs(r[i][1]) * h[1] + std::fabs(r[i][2]) * h[2];
        smoke::MovingObstacle prop;
        prop.shape = Shape::Box;
        prop.centre = b.position;
        prop.halfExtents = {e[0], e[1], e[2]};
        prop.velocity = b.velocity;
        out.push_back(prop);
    }
    // Movers: each brush's box where it is now, moving at the mover's velocity (doors and plats
    // are axis-aligned boxes, for which the box is the brush).
    const sim::Movers& movers = sim.movers();
    for (std::size_t i = 0; i < movers.count(); ++i) {
        for (const auto& b : movers.brushBounds(i)) {
            smoke::MovingObstacle m;
            m.shape = Shape::Box;
            m.centre = (b.min + b.max) * 0.5 + movers.offset(i);
            m.halfExtents = (b.max - b.min) * 0.5;
            m.velocity = movers.velocity(i);
            out.push_back(m);
        }
    }
    for (const auto& g : sim.grenades()) {
        smoke::MovingObstacle grenade;
        grenade.shape = Shape::Sphere;
        grenade.centre = g.position;
        grenade.radius = g.radius;
        grenade.velocity = g.velocity;
        out.push_back(grenade);
    }
    return out;
}

}  // namespace obscura
