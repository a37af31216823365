// The candidate list with a skin per particle (contact/adaptive_skin.hpp) against its own guarantee: every pair
// closer than the thickness that was farther than twice it apart at rest is in the list, checked by comparing
// every pair on a hand-made pair, on random walks and on the states of a folding strip.
#include "contact/adaptive_skin.hpp"
#include "contact/obstacles.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "model/fabric.hpp"

#include "folding_strip.hpp"

#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <random>

using namespace cloth;

namespace {

constexpr double delta = 0.01;

// Every pair of x closer than delta, farther than 2 delta apart at rest, that `list` misses.
int missed(const AdaptiveSkinList& list, const Eigen::VectorXd& x, const Eigen::VectorXd& rest) {
  int count = 0;
  const auto n = static_cast<int>(x.size() / 3);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if ((x.segment<3>(3 * b) - x.segment<3>(3 * a)).norm() < delta &&
          (rest.segment<3>(3 * b) - rest.segment<3>(3 * a)).norm() > 2 * delta * (1 + 1e-9) && !list.holds(a, b))
        ++count;
  return count;
}

}  // namespace

TEST_CASE("a particle queried after its partner moved takes its radius from the partner's ball, not its position") {
  // Two particles far apart at rest, on a line; r_max = delta / 2, so the reach is 2 delta.
  Eigen::VectorXd rest(6), x(6);
  rest << 0, 0, 0, 100 * delta, 0, 0;
  AdaptiveSkinList list(rest, delta, 0.5 * delta, 0.1 * delta, false);
  x << 0, 0, 0, 5 * delta, 0, 0;
  CHECK(list.update(x) == 2);
  CHECK(list.radius(0) == doctest::Approx(0.5 * delta).epsilon(1e-12));
  // a drifts to the edge of its ball, away from b; b comes to 1.9 delta and is queried again. It sees a 2.4 delta
  // away, beyond the reach: a radius from that clearance would be (2 - 1) delta / 2 = delta / 2. From a's ball it
  // is 1.9 - 0.5 - 1 = 0.4 delta.
  x[0] = -0.5 * delta;
  x[3] = 1.9 * delta;
  CHECK(list.update(x) == 1);
  CHECK(list.radius(1) == doctest::Approx(0.4 * delta).epsilon(1e-9));
  CHECK_FALSE(list.holds(0, 1));
  // Both now move to the far edges of their balls, towards each other, without being queried: they are still
  // delta apart (at b's rival radius delta / 2 they would be 0.9 delta apart, a contact the list does not hold).
  x[0] = 0.5 * delta * (1 - 1e-9);
  x[3] = (1.9 - 0.4 * (1 - 1e-9)) * delta;
  CHECK(list.update(x) == 0);
  CHECK(x[3] - x[0] >= delta * (1 - 1e-12));
}

TEST_CASE("random walks: the list with a skin per particle holds every contact after every move") {
  std::mt19937 rng(27);
  const int n = 300;
  Eigen::VectorXd rest(3 * n), x(3 * n);
  std::uniform_real_distribution<double> box(0, 12 * delta), unit(-1, 1);
  for (int p = 0; p < n; ++p) rest.segment<3>(3 * p) = Eigen::Vector3d(100 * delta * p, 0, 0);  // all apart at rest
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = box(rng);
  for (const bool follow : {false, true}) {
    CAPTURE(follow);
    AdaptiveSkinList list(rest, delta, 0.5 * delta, 0.25 * delta, follow);
    Eigen::VectorXd y = x;
    int checked = 0, contacts = 0, queried = 0;
    for (int step = 0; step < 200; ++step) {
      const Eigen::Vector3d common(0.02 * delta, 0, -0.03 * delta);  // a drift common to all, as in a fall
      for (int p = 0; p < n; ++p) y.segment<3>(3 * p) += common + 0.1 * delta * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      const int q = list.update(y);
      if (step > 0) queried += q;
      checked += missed(list, y, rest) == 0 ? 1 : 0;
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) contacts += (y.segment<3>(3 * b) - y.segment<3>(3 * a)).norm() < delta ? 1 : 0;
    }
    CHECK(checked == 200);
    CHECK(contacts > 1000);              // the walks do bring particles into contact
    CHECK(queried < 199 * n / 2);        // and most steps keep most references
    CHECK(list.pairs() > 0);
  }
}

TEST_CASE("a folding strip: the list with a skin per particle holds every contact, checked every tenth step") {
  const Scene scene(cloth_test::standing_strip(delta));
  ForceField field(scene);
  const ContactModel model = cloth_test::ground_and_self(delta);
  ContactStepper stepper(make_stepper("symplectic_euler", field), model);
  const Eigen::VectorXd rest = scene.initial_positions();
  AdaptiveSkinList list(rest, delta, 0.5 * delta, 0.25 * delta, false);
  Eigen::VectorXd x = rest, v = scene.initial_velocities();
  int missed_total = 0, checks = 0;
  long long held = 0;
  for (int k = 0; k < 1600; ++k) {  // 0.8 s: the strip falls and lies folded on the ground
    REQUIRE(stepper.step(5e-4, x, v));
    list.update(x);
    if (k % 10 == 9) {
      missed_total += missed(list, x, rest);
      held += list.pairs();
      ++checks;
    }
  }
  CHECK(missed_total == 0);
  CHECK(held > 1000);  // the strip's layers met, and the list held their pairs
  CHECK(list.queries() < 1600LL * 400 / 4);  // fewer queries than a rebuild of every particle every fourth step
  CHECK(list.mean_radius() >= 0.25 * delta);
}
