// Self-collision's parts against independent truth: the spatial hash finds exactly the close pairs that comparing
// every pair finds, the pair response conserves linear momentum, and the passes that skip unmoved pairs end where
// full passes do, and the obstacle corrections that skip particles clear of every obstacle end where full ones do.
#include "contact/self_collision.hpp"
#include "contact/spatial_hash.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>

using namespace cloth;

TEST_CASE("the spatial hash finds exactly the pairs a brute-force search finds, on random clouds") {
  std::mt19937 rng(11);
  struct Cloud {
    int particles;
    double box;     // the cloud fills [-box/2, box/2]^3: negative cells are hashed too
    double r;
    int buckets;    // few buckets force distinct cells into one bucket
  };
  const Cloud clouds[] = {{500, 1.0, 0.08, 1000}, {2000, 0.5, 0.02, 4000}, {300, 1.0, 0.2, 7}, {1000, 100.0, 3.0, 50}};
  for (const Cloud& cloud : clouds) {
    CAPTURE(cloud.particles);
    CAPTURE(cloud.buckets);
    std::uniform_real_distribution<double> coordinate(-cloud.box / 2, cloud.box / 2);
    Eigen::VectorXd x(3 * cloud.particles);
    for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = coordinate(rng);
    SpatialHash hash(cloud.r, cloud.buckets);
    hash.build(x);
    std::vector<std::pair<int, int>> found;
    hash.pairs_within(cloud.r, found);
    std::vector<std::pair<int, int>> truth = pairs_within_brute_force(x, cloud.r);
    std::sort(found.begin(), found.end());
    std::sort(truth.begin(), truth.end());
    CHECK(truth.size() > 20);  // the clouds are dense enough for the comparison to mean something
    CHECK(found == truth);     // the same pairs, each once
  }
}

TEST_CASE("the mesh-aware hash finds exactly the close pairs that were apart at rest, as a brute-force search does") {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);
  const int particles = 1500;
  const double r = 0.06, apart = 0.3;  // about a third of the close pairs were within `apart` at rest
  Eigen::VectorXd x(3 * particles), rest(3 * particles);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = coordinate(rng);
  for (Eigen::Index k = 0; k < x.size(); ++k) rest[k] = coordinate(rng);
  SpatialHash hash(r, 3000);
  hash.build(x, rest);
  std::vector<std::pair<int, int>> found, truth, near_at_rest;
  hash.pairs_within(r, found, apart);
  for (const auto& p : pairs_within_brute_force(x, r))
    ((rest.segment<3>(3 * p.second) - rest.segment<3>(3 * p.first)).norm() > apart ? truth : near_at_rest).push_back(p);
  std::sort(found.begin(), found.end());
  CHECK(truth.size() > 100);
  CHECK(near_at_rest.size() > 20);  // the filter has pairs to leave out
  CHECK(found == truth);
  CHECK(hash.distance_tests() >= static_cast<long long>(found.size() + near_at_rest.size()));
}

TEST_CASE("the self-contact response conserves linear momentum and parts a pair to the thickness") {
  const double thickness = 0.01;
  Eigen::VectorXd x(6), v(6);
  x << 0.1, 0.2, 0.3, 0.1 + 0.004, 0.2 + 0.002, 0.3 - 0.001;  // 4.6 mm apart, inside a 1 cm shell
  v << 1.5, -0.5, 2.0, -3.0, 0.25, 1.0;                          // approaching
  const Eigen::Vector3d momentum = v.head<3>() + v.tail<3>();
  const Eigen::Vector3d centre = x.head<3>() + x.tail<3>();
  const Eigen::Vector3d n = (x.tail<3>() - x.head<3>()).normalized();
  const Eigen::Vector3d tangential = (v.tail<3>() - v.head<3>()) - (v.tail<3>() - v.head<3>()).dot(n) * n;
  REQUIRE((v.tail<3>() - v.head<3>()).dot(n) < -1);
  CHECK(resolve_self_contacts({{0, 1}}, thickness, x, v) == 1);
  CHECK((v.head<3>() + v.tail<3>() - momentum).norm() < 1e-15 * momentum.norm() * 4);
  CHECK((x.head<3>() + x.tail<3>() - centre).norm() < 1e-15 * centre.norm() * 4);
  CHECK((x.tail<3>() - x.head<3>()).norm() == doctest::Approx(thickness).epsilon(1e-12));
  const Eigen::Vector3d relative = v.tail<3>() - v.head<3>();
  CHECK(std::abs(relative.dot(n)) < 1e-15);               // the approach stopped
  CHECK((relative - tangential).norm() < 1e-15);          // the sliding of one past the other kept
}

TEST_CASE("the hash keeps every pair of a cloud beyond its key range, where its cells merge") {
  // Cells are indexed from -2^20 to 2^20 - 1 along each axis and clamped beyond: a cloud 20 km out, 2 million cells
  // of 1 cm from the origin, lies in one merged column of merged cells, and every pair must still be found.
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  const int particles = 400;
  const double r = 0.01, far = 2e4;
  Eigen::VectorXd x(3 * particles);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = (k % 3 == 1 ? -far : far) + coordinate(rng);
  SpatialHash hash(r, 800);
  hash.build(x);
  std::vector<std::pair<int, int>> found;
  hash.pairs_within(r, found);
  std::vector<std::pair<int, int>> truth = pairs_within_brute_force(x, r);
  std::sort(found.begin(), found.end());
  std::sort(truth.begin(), truth.end());
  CHECK(truth.size() > 20);
  CHECK(found == truth);
}

TEST_CASE("a pass over the pairs with a moved particle ends where a full pass over every pair ends") {
  // A crumpled cloud of 600 particles 1 cm thick, squeezed into a 6 cm cube so that parting one pair pushes
  // others together: the passes of SelfCollision (the first over every candidate, the later ones over the pairs a
  // particle of which moved, or over every candidate when those are many) against full passes of
  // resolve_self_contacts over the same list, to the last bit.
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> coordinate(0.0, 0.06), rest_coordinate(0.0, 1.0), velocity(-1.0, 1.0);
  const int particles = 600;
  const double thickness = 0.01;
  Eigen::VectorXd x(3 * particles), v(3 * particles), rest(3 * particles);
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    x[k] = coordinate(rng);
    v[k] = velocity(rng);
    rest[k] = rest_coordinate(rng);
  }
  SelfCollision self(rest, thickness);
  self.find_candidates(x);
  const std::vector<std::pair<int, int>> pairs = self.candidates();
  REQUIRE(pairs.size() > 1000);
  Eigen::VectorXd x_full = x, v_full = v;
  int passes = 0, passes_full = 0;
  for (int corrected = self.resolve(x, v); corrected > 0 && passes < 30; corrected = self.resolve_again(x, v)) ++passes;
  while (resolve_self_contacts(pairs, thickness, x_full, v_full, SelfCollision::response_slack) > 0 && passes_full < 30) ++passes_full;
  CHECK(passes > 3);  // the passes after the first have something to do
  // Both kinds of later pass were taken: over every candidate (the moved particles hold more than a quarter of
  // them), and over the marked ones.
  CHECK(self.work().full_passes > 1);
  CHECK(self.work().full_passes < self.work().passes - 1);
  CHECK(passes == passes_full);
  CHECK(x == x_full);
  CHECK(v == v_full);
}

TEST_CASE("the sweep and the corrections between passes end where the full obstacle corrections end") {
  // A crumpled cloud 1 cm thick on the ground and around a sphere, its particles moved from a start x0: the one
  // sweep (clamp, obstacles) against the clamp followed by a full correction, and after a pass of the response the
  // correction of the particles that may have come within an obstacle's shell against that of every particle moved,
  // to the last bit. A clearance that were not a bound on how far a signed distance can change would differ.
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> coordinate(0.0, 0.08), step(-0.004, 0.004), rest_coordinate(0.0, 1.0);
  const int particles = 600;
  const double thickness = 0.01, h = 1e-3;
  ContactModel model;
  model.thickness = thickness;
  model.friction = {0.3, 0.2};
  model.obstacles = {HalfSpace{}, Sphere{Eigen::Vector3d(0.04, 0.04, 0.05), 0.02}};
  Eigen::VectorXd x0(3 * particles), x(3 * particles), v(3 * particles), rest(3 * particles);
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    x0[k] = coordinate(rng);
    x[k] = x0[k] + step(rng);
    v[k] = x[k] - x0[k];
    rest[k] = rest_coordinate(rng);
  }
  v /= h;
  SelfCollision self(rest, thickness);
  Eigen::VectorXd x_full = x, v_full = v;
  const int contacts = self.clamp_and_correct(model, x0, h, x, v);
  (void)self.clamp(x0, h, x_full, v_full);
  CHECK(contacts == resolve_obstacle_contacts(model, x0, x_full, v_full));
  CHECK(contacts > 50);  // the ground and the sphere both act
  CHECK(x == x_full);
  CHECK(v == v_full);
  self.find_candidates(x);
  REQUIRE(self.resolve(x, v) > 100);
  resolve_self_contacts(self.candidates(), thickness, x_full, v_full, SelfCollision::response_slack);
  const int corrected = self.correct_moved(model, x0, x, v);
  CHECK(corrected == resolve_obstacle_contacts(model, self.moved(), x0, x_full, v_full));
  CHECK(corrected > 10);  // some moved particles were pushed into an obstacle
  CHECK(x == x_full);
  CHECK(v == v_full);
}
