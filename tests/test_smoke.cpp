// Placeholder removed once the real suites exist.
#include <doctest/doctest.h>
#include "cloth/force_field.hpp"
TEST_CASE("spring counts of the report's 20 x 20 cloth") {
  cloth::Scene scene(cloth::SceneParams{});
  CHECK(scene.springs().count(cloth::SpringFamily::structural) == 760);
  CHECK(scene.springs().count(cloth::SpringFamily::shear) == 722);
  CHECK(scene.springs().count(cloth::SpringFamily::flexion) == 720);
}
#include "integrators/methods.hpp"
#include "integrators/simulate.hpp"
#include <iostream>
TEST_CASE("smoke: every method runs the report scene") {
  for (const auto& m : cloth::method_names()) {
    cloth::SceneParams p; p.stiffness = 50;
    cloth::Scene scene(p);
    cloth::ForceField field(scene);
    auto stepper = cloth::make_stepper(m, field);
    cloth::RunSettings rs; rs.dt = 0.01; rs.t_end = 2;
    auto r = cloth::simulate(*stepper, rs);
    std::cout << m << " " << r.message << " E0=" << r.energy.front().energy.total() << " E=" << r.energy.back().energy.total()
              << " newton=" << r.counters.newton_iterations << " wall=" << r.wall_seconds << "\n";
  }
}
