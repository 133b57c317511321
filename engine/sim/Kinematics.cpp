#include "sim/Kinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace neptus::sim {

namespace {

double approach(double value, double target, double step)
{
    return value + std::clamp(target - value, -step, step);
}

void climb(Motion &motion, const double *down, double dt, const Limits &limits)
{
    if (limits.surfaceOnly)
        motion.ned.z() = 0;
    else if (down)
        motion.ned.z() = approach(motion.ned.z(), *down, limits.verticalRate * dt);
}

void forward(Motion &motion, double dt)
{
    motion.ned.x() += motion.speed * dt * std::cos(motion.psi);
    motion.ned.y() += motion.speed * dt * std::sin(motion.psi);
}

} // namespace

double Limits::arrivalRadius(double speed) const
{
    return std::max(3.0, 1.2 * speed / turnRate);
}

bool steer(Motion &motion, const Eigen::Vector2d &target, double speed, const double *down, double dt,
           const Limits &limits)
{
    const Eigen::Vector2d to = target - motion.ned.head<2>();
    const double distance = to.norm();
    speed = std::clamp(speed, limits.minSpeed, limits.maxSpeed);
    const double radius = limits.arrivalRadius(speed);
    if (distance > 1e-6) {
        const double error = std::remainder(std::atan2(to.y(), to.x()) - motion.psi, 2 * std::numbers::pi);
        motion.psi = std::remainder(motion.psi + std::clamp(error, -limits.turnRate * dt, limits.turnRate * dt),
                                    2 * std::numbers::pi);
    }
    motion.speed = approach(motion.speed, speed, limits.acceleration * dt);
    forward(motion, dt);
    climb(motion, down, dt, limits);
    return (target - motion.ned.head<2>()).norm() <= radius;
}

void hold(Motion &motion, const double *down, double dt, const Limits &limits)
{
    if (limits.minSpeed > 0) { // it cannot stop: it circles at its slowest
        motion.speed = approach(motion.speed, limits.minSpeed, limits.acceleration * dt);
        motion.psi = std::remainder(motion.psi + limits.turnRate * dt, 2 * std::numbers::pi);
    } else {
        motion.speed = approach(motion.speed, 0, limits.acceleration * dt);
    }
    forward(motion, dt);
    climb(motion, down, dt, limits);
}

} // namespace neptus::sim
