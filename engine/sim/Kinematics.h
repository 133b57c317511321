#pragma once

#include <Eigen/Core>

namespace neptus::sim {

// How a simulated vehicle moves: what it can do (Limits, per kind) and
// where it is (Motion, in metres north, east and down of its reference
// point; down is depth under water and minus the height in the air).
struct Limits
{
    double maxSpeed = 2.0;      // m/s through the water or air
    double minSpeed = 0;        // a UAV stalls below this
    double acceleration = 0.5;  // m/s²
    double turnRate = 0.35;     // rad/s
    double verticalRate = 0.3;  // m/s, diving, climbing
    bool surfaceOnly = false;   // a boat: down stays 0
    double bottomDepth = 30;    // sea floor under the vehicle (for altitude z), m

    static Limits auv() { return {}; }
    static Limits asv() { return {3.0, 0, 0.8, 0.5, 0, true, 30}; }
    static Limits uav() { return {25.0, 12.0, 3.0, 0.3, 3.0, false, 0}; }

    // How close counts as there: the vehicle's turning radius with a margin, 3 m at least.
    double arrivalRadius(double speed) const;
};

struct Motion
{
    Eigen::Vector3d ned = Eigen::Vector3d::Zero();
    double psi = 0;   // heading, rad from north
    double speed = 0; // m/s along the heading
};

// One step of `dt` seconds towards `target` (north, east) at `speed`,
// turning, speeding up and slowing down within `limits`, and towards
// `down` at the vertical rate when given. True once within the arrival radius.
bool steer(Motion &motion, const Eigen::Vector2d &target, double speed, const double *down, double dt,
           const Limits &limits);
// One step holding still (a UAV circles where it is instead).
void hold(Motion &motion, const double *down, double dt, const Limits &limits);

} // namespace neptus::sim
