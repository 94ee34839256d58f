#include "scan/scene_layout.hpp"
#include "util/angles.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace spinhash::host {
namespace {

constexpr uint64_t kLayoutStream = 0x7200;
constexpr uint32_t kRestSamples = 5;     // per side of a vehicle footprint, for the ground plane fit
constexpr double kTileMargin = 1.0;      // m: objects stay this far inside the tile
constexpr double kClearance = 1.5;       // m between objects, but the side-by-side pair
constexpr double kCurbMargin = 0.5;      // m: vehicles stand clear of the curb, not across it
constexpr double kCrownClearance = 0.5;  // m between a crown's underside and what it overhangs
// m from the overhung vehicle's side to its trunk's axis: the clearance,
// the thickest trunk (scene_clutter.cpp) and a little more.
constexpr double kTrunkOffsetMin = kClearance + 0.4, kTrunkOffsetMax = kClearance + 0.9;
constexpr double kFreeCrownShift = 1.0;  // m: a free tree's crown off its trunk
// m between vehicle centres beyond which a crown over one cannot reach the other.
constexpr double kCrownReach = 12.0;

bool is_vehicle(SceneObjectKind k) {
  return k == SceneObjectKind::kVehicle || k == SceneObjectKind::kUnknownVehicle;
}
bool is_structure(SceneObjectKind k) {
  return k == SceneObjectKind::kBuilding || k == SceneObjectKind::kWall;
}

// Projection of the mesh's vertices on the line origin + s dir: [lo, hi].
Eigen::Vector2d interval_along(const Mesh& m, const Eigen::Vector2d& origin, const Eigen::Vector2d& dir) {
  Eigen::Vector2d r(INFINITY, -INFINITY);
  for (std::size_t i = 0; i < m.vertex_count(); ++i) {
    const double s = (m.vertex(i).head<2>() - origin).dot(dir);
    r[0] = std::min(r[0], s);
    r[1] = std::max(r[1], s);
  }
  return r;
}

// Whether p may join `placed`: inside the tile, clear of everything on the
// ground, crowns only over what is lower than them.
bool fits(const PlacedObject& p, const std::vector<PlacedObject>& placed, double size, const Terrain& t) {
  if (!inside_tile(p.base, size, kTileMargin)) return false;
  if (p.has_crown && !inside_tile(p.crown, size, 0.0)) return false;
  if (is_vehicle(p.truth.kind)) {
    const Footprint& f = p.base;
    const double side = t.curb_distance(f.center.x(), f.center.y());
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector2d q = f.center + ((c & 1) ? 1.0 : -1.0) * f.half.x() * f.axis() +
                                ((c & 2) ? 1.0 : -1.0) * f.half.y() * f.lateral();
      const double d = t.curb_distance(q.x(), q.y());
      if (d * side <= 0.0 || std::abs(d) < kCurbMargin) return false;
    }
  }
  for (const PlacedObject& q : placed) {
    if (footprints_overlap(p.base, q.base, kClearance)) return false;
    for (int k = 0; k < 2; ++k) {  // each of the pair as the tree
      const PlacedObject& tree = k ? q : p;
      const PlacedObject& other = k ? p : q;
      if (!tree.has_crown) continue;
      const Footprint& under = other.has_crown ? other.crown : other.base;
      if (!footprints_overlap(tree.crown, under, 0.0)) continue;
      if (other.has_crown || is_structure(other.truth.kind)) return false;
      if (other.top + kCrownClearance > tree.crown_bottom) return false;
    }
  }
  return true;
}

class Layout {
 public:
  Layout(const SceneOptions& o, const Terrain& t, std::vector<PlacedObject>* out)
      : o_(o), t_(t), out_(out), rng_(mix_seed(o.seed, kLayoutStream)) {}

  Eigen::Vector2d random_xy() {
    const double half = 0.5 * o_.size;
    const double x = rng_.uniform(-half, half);
    return {x, rng_.uniform(-half, half)};
  }
  double random_yaw() { return rng_.uniform(0.0, 2.0 * kPi); }
  SeededRandom* rng() { return &rng_; }

  // Draws with make() until the object fits, at most `attempts` times.
  template <class Make>
  bool try_place(Make make, uint32_t attempts) {
    for (uint32_t attempt = 0; attempt < attempts; ++attempt) {
      PlacedObject p = make();
      if (!fits(p, *out_, o_.size, t_)) continue;
      out_->push_back(std::move(p));
      return true;
    }
    return false;
  }

  // try_place with kMaxPlacementAttempts; false with *error.
  template <class Make>
  bool place(const char* what, uint32_t index, Make make, std::string* error) {
    if (try_place(make, kMaxPlacementAttempts)) return true;
    *error = std::string("cannot place ") + what + " " + std::to_string(index + 1) +
             " clear of the others in a " + std::to_string(o_.size) + " m tile after " +
             std::to_string(kMaxPlacementAttempts) + " attempts: use a larger --size or fewer objects";
    return false;
  }

  // The parked pair: b beside a, their footprints a gap in
  // [kSideBySideGapMin, kSideBySideGapMax] apart, both clear of the rest.
  bool place_pair(const Mesh& a, const Mesh& b, std::string* error) {
    for (uint32_t attempt = 0; attempt < kMaxPlacementAttempts; ++attempt) {
      const double yaw = random_yaw();
      PlacedObject pa = place_vehicle(a, SceneObjectKind::kVehicle, t_, random_xy(), yaw);
      if (!fits(pa, *out_, o_.size, t_)) continue;
      const double gap = rng_.uniform(kSideBySideGapMin + 0.1, kSideBySideGapMax - 0.1);
      const double side = rng_.chance(0.5) ? 1.0 : -1.0;
      const double yaw_b = rng_.chance(0.5) ? yaw : yaw + kPi;  // parked either way round
      const Eigen::Vector2d l = side * pa.base.lateral();
      const Eigen::Vector2d ia = interval_along(pa.mesh, pa.base.center, l);
      Eigen::Vector2d at = pa.base.center + (ia[1] + gap + 0.5 * b.bounding_box().size().y()) * l;
      PlacedObject pb;
      for (int pass = 0; pass < 2; ++pass) {  // a second pass corrects for the tilt
        pb = place_vehicle(b, SceneObjectKind::kVehicle, t_, at, yaw_b);
        const double real_gap = interval_along(pb.mesh, pa.base.center, l)[0] - ia[1];
        at += (gap - real_gap) * l;
      }
      const double real_gap = interval_along(pb.mesh, pa.base.center, l)[0] - ia[1];
      if (!(real_gap >= kSideBySideGapMin && real_gap <= kSideBySideGapMax)) continue;
      if (!fits(pb, *out_, o_.size, t_)) continue;
      pa.truth.flags |= kSideBySide;
      pb.truth.flags |= kSideBySide;
      out_->push_back(std::move(pa));
      out_->push_back(std::move(pb));
      return true;
    }
    *error = "cannot place the side-by-side pair in a " + std::to_string(o_.size) + " m tile after " +
             std::to_string(kMaxPlacementAttempts) + " attempts: use a larger --size or fewer objects";
    return false;
  }

  // A row of parked vehicles (a parking lot's row): each beside the one
  // before, a gap in [kSideBySideGapMin, kSideBySideGapMax] apart, parked
  // either way round, all clear of the rest.
  bool place_row(const std::vector<const Mesh*>& row, std::string* error) {
    for (uint32_t attempt = 0; attempt < kMaxPlacementAttempts; ++attempt) {
      const double yaw = random_yaw();
      std::vector<PlacedObject> placed;
      placed.push_back(place_vehicle(*row[0], SceneObjectKind::kVehicle, t_, random_xy(), yaw));
      if (!fits(placed[0], *out_, o_.size, t_)) continue;
      const Eigen::Vector2d l = placed[0].base.lateral();
      bool ok = true;
      for (size_t k = 1; k < row.size() && ok; ++k) {
        const PlacedObject& prev = placed.back();
        const double gap = rng_.uniform(kSideBySideGapMin + 0.1, kSideBySideGapMax - 0.1);
        const double yaw_k = rng_.chance(0.5) ? yaw : yaw + kPi;
        const Eigen::Vector2d ip = interval_along(prev.mesh, prev.base.center, l);
        Eigen::Vector2d at = prev.base.center + (ip[1] + gap + 0.5 * row[k]->bounding_box().size().y()) * l;
        PlacedObject pk;
        for (int pass = 0; pass < 2; ++pass) {  // a second pass corrects for the tilt
          pk = place_vehicle(*row[k], SceneObjectKind::kVehicle, t_, at, yaw_k);
          at += (gap - (interval_along(pk.mesh, prev.base.center, l)[0] - ip[1])) * l;
        }
        const double real_gap = interval_along(pk.mesh, prev.base.center, l)[0] - ip[1];
        std::vector<PlacedObject> others = *out_;
        others.insert(others.end(), placed.begin(), placed.end() - 1);  // the previous is its neighbour
        ok = real_gap >= kSideBySideGapMin && real_gap <= kSideBySideGapMax && fits(pk, others, o_.size, t_);
        placed.push_back(std::move(pk));
      }
      if (!ok) continue;
      for (PlacedObject& p : placed) {
        p.truth.flags |= kSideBySide;
        out_->push_back(std::move(p));
      }
      return true;
    }
    *error = "cannot place a row of " + std::to_string(row.size()) + " parked vehicles in a " +
             std::to_string(o_.size) + " m tile after " + std::to_string(kMaxPlacementAttempts) +
             " attempts: use a larger --size or fewer objects";
    return false;
  }

  // A tree whose crown overhangs one of the `count` vehicles from `first`:
  // the last if it fits there (its crown inside the tile, its trunk clear of
  // everything), else the one before, ...
  bool place_tree_over(std::size_t first, uint32_t count, std::string* error) {
    for (uint32_t k = count; k-- > 0;) {
      const PlacedObject target = (*out_)[first + k];
      // The crown clears every vehicle it may reach, not only its target.
      double clear = -INFINITY;
      for (const PlacedObject& q : *out_) {
        if (is_vehicle(q.truth.kind) && (q.base.center - target.base.center).norm() < kCrownReach)
          clear = std::max(clear, q.top + kCrownClearance);
      }
      auto make = [&]() {
        const double side = rng_.chance(0.5) ? 1.0 : -1.0;
        const Eigen::Vector2d l = side * target.base.lateral();
        const Eigen::Vector2d at =
            target.base.center + (target.base.half.y() + rng_.uniform(kTrunkOffsetMin, kTrunkOffsetMax)) * l +
            rng_.uniform(-0.5, 0.5) * target.base.half.x() * target.base.axis();
        const Eigen::Vector2d crown_at =
            target.base.center + rng_.uniform(0.0, 0.5) * target.base.half.y() * l;
        return make_tree(t_, at, crown_at, clear, &rng_);
      };
      if (try_place(make, kMaxPlacementAttempts / count + 1)) {
        (*out_)[first + k].truth.flags |= kUnderTree;
        return true;
      }
    }
    *error = "cannot place a tree over any vehicle in a " + std::to_string(o_.size) +
             " m tile: use a larger --size or fewer objects";
    return false;
  }

 private:
  const SceneOptions& o_;
  const Terrain& t_;
  std::vector<PlacedObject>* out_;
  SeededRandom rng_;
};

// Marks every vehicle over whose footprint some crown vertex lies.
void mark_under_trees(std::vector<PlacedObject>* placed) {
  for (PlacedObject& v : *placed) {
    if (!is_vehicle(v.truth.kind)) continue;
    for (const PlacedObject& tree : *placed) {
      if (!tree.has_crown || !footprints_overlap(tree.crown, v.base, 0.0)) continue;
      for (std::size_t i = 0; i < tree.mesh.vertex_count(); ++i) {
        const Eigen::Vector2d d = tree.mesh.vertex(i).head<2>() - v.base.center;
        if (std::abs(d.dot(v.base.axis())) < v.base.half.x() &&
            std::abs(d.dot(v.base.lateral())) < v.base.half.y() &&
            tree.mesh.vertex(i).z() > tree.crown_bottom - kCrownClearance) {
          v.truth.flags |= kUnderTree;
          break;
        }
      }
    }
  }
}

}  // namespace

Eigen::Vector2d Footprint::axis() const { return {std::cos(heading), std::sin(heading)}; }
Eigen::Vector2d Footprint::lateral() const { return {-std::sin(heading), std::cos(heading)}; }

bool footprints_overlap(const Footprint& a, const Footprint& b, double clearance) {
  const Eigen::Vector2d axes[4] = {a.axis(), a.lateral(), b.axis(), b.lateral()};
  const Eigen::Vector2d d = b.center - a.center;
  for (const Eigen::Vector2d& u : axes) {
    const double ra = a.half.x() * std::abs(a.axis().dot(u)) + a.half.y() * std::abs(a.lateral().dot(u));
    const double rb = b.half.x() * std::abs(b.axis().dot(u)) + b.half.y() * std::abs(b.lateral().dot(u));
    if (std::abs(d.dot(u)) > ra + rb + clearance) return false;
  }
  return true;
}

Footprint footprint_of(const Mesh& mesh, double heading) {
  Footprint f;
  f.heading = heading;
  const Eigen::Vector2d ia = interval_along(mesh, Eigen::Vector2d::Zero(), f.axis());
  const Eigen::Vector2d il = interval_along(mesh, Eigen::Vector2d::Zero(), f.lateral());
  f.center = 0.5 * (ia[0] + ia[1]) * f.axis() + 0.5 * (il[0] + il[1]) * f.lateral();
  f.half = Eigen::Vector2d(0.5 * (ia[1] - ia[0]), 0.5 * (il[1] - il[0]));
  return f;
}

bool inside_tile(const Footprint& f, double size, double margin) {
  const double limit = 0.5 * size - margin;
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d q = f.center + ((c & 1) ? 1.0 : -1.0) * f.half.x() * f.axis() +
                              ((c & 2) ? 1.0 : -1.0) * f.half.y() * f.lateral();
    if (std::abs(q.x()) > limit || std::abs(q.y()) > limit) return false;
  }
  return true;
}

Eigen::Matrix4d rest_on_terrain(const Mesh& model, const Terrain& terrain, const Eigen::Vector2d& at,
                                double yaw) {
  const Box3 box = model.bounding_box();
  const Eigen::Vector3d base(box.center().x(), box.center().y(), box.lo.z());
  // Least-squares plane z = a x + b y + c through the terrain under the footprint.
  const Eigen::Vector2d axis(std::cos(yaw), std::sin(yaw)), lateral(-std::sin(yaw), std::cos(yaw));
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (uint32_t j = 0; j < kRestSamples; ++j) {
    for (uint32_t i = 0; i < kRestSamples; ++i) {
      const double u = (double(i) / (kRestSamples - 1) - 0.5) * box.size().x();
      const double v = (double(j) / (kRestSamples - 1) - 0.5) * box.size().y();
      const Eigen::Vector2d d = u * axis + v * lateral;
      const Eigen::Vector3d row(d.x(), d.y(), 1.0);
      ata += row * row.transpose();
      atb += row * terrain.height(at.x() + d.x(), at.y() + d.y());
    }
  }
  const Eigen::Vector3d abc = ata.ldlt().solve(atb);
  const Eigen::Vector3d normal = Eigen::Vector3d(-abc.x(), -abc.y(), 1.0).normalized();
  const Eigen::Matrix3d r =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal).toRotationMatrix() *
      Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Vector3d t = Eigen::Vector3d(at.x(), at.y(), 0.0) - r * base;
  // Lower (or raise) it until its lowest vertex over the terrain touches.
  double lift = -INFINITY;
  for (std::size_t i = 0; i < model.vertex_count(); ++i) {
    const Eigen::Vector3d p = r * model.vertex(i) + t;
    lift = std::max(lift, terrain.height(p.x(), p.y()) - p.z());
  }
  t.z() += lift;
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  pose.topLeftCorner<3, 3>() = r;
  pose.topRightCorner<3, 1>() = t;
  return pose;
}

PlacedObject place_vehicle(const Mesh& model, SceneObjectKind kind, const Terrain& terrain,
                           const Eigen::Vector2d& at, double yaw) {
  PlacedObject p;
  const Eigen::Matrix4d pose = rest_on_terrain(model, terrain, at, yaw);
  p.mesh = model;
  p.mesh.apply_transform(pose);
  const Eigen::Vector3d x = pose.topLeftCorner<3, 3>().col(0);
  const double heading = std::atan2(x.y(), x.x());
  p.base = footprint_of(p.mesh, heading);
  p.top = p.mesh.bounding_box().hi.z();
  p.truth.kind = kind;
  p.truth.model = model.name;
  p.truth.pose = pose;
  const double ground = terrain.height(p.base.center.x(), p.base.center.y());
  p.truth.center = Eigen::Vector3d(p.base.center.x(), p.base.center.y(), ground);
  p.truth.extent = Eigen::Vector3d(2.0 * p.base.half.x(), 2.0 * p.base.half.y(), p.top - ground);
  p.truth.heading_deg = heading * kRadToDeg;
  return p;
}

bool lay_out_scene(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown, const SceneOptions& o,
                   const Terrain& t, std::vector<PlacedObject>* out, std::string* error) {
  out->clear();
  Layout lay(o, t, out);
  SeededRandom* rng = lay.rng();
  for (uint32_t k = 0; k < o.buildings; ++k) {
    if (!lay.place(
            "building", k, [&] { return make_building(t, lay.random_xy(), lay.random_yaw(), rng); }, error))
      return false;
  }
  for (uint32_t k = 0; k < o.walls; ++k) {
    if (!lay.place(
            "wall", k, [&] { return make_wall(t, lay.random_xy(), lay.random_yaw(), rng); }, error))
      return false;
  }
  // Which database meshes: a seeded shuffle, repeating when more are asked for than given.
  std::vector<uint32_t> order(vehicles.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  for (uint32_t i = static_cast<uint32_t>(order.size()); i > 1; --i)
    std::swap(order[i - 1], order[rng->below(i)]);
  auto model = [&](uint32_t k) -> const Mesh& { return vehicles[order[k % order.size()]]; };
  const std::size_t first_vehicle = out->size();
  uint32_t k = 0;
  if (o.vehicles >= 2) {
    if (!lay.place_pair(model(0), model(1), error)) return false;
    k = 2;
  }
  for (uint32_t r = 0; r < o.parked_rows && k + o.row_length <= o.vehicles; ++r) {
    std::vector<const Mesh*> row;
    for (uint32_t j = 0; j < o.row_length; ++j) row.push_back(&model(k + j));
    if (!lay.place_row(row, error)) return false;
    k += o.row_length;
  }
  for (; k < o.vehicles; ++k) {
    const Mesh& m = model(k);
    auto make = [&] {
      return place_vehicle(m, SceneObjectKind::kVehicle, t, lay.random_xy(), lay.random_yaw());
    };
    if (!lay.place("vehicle", k, make, error)) return false;
  }
  uint32_t trees = 0;
  if (o.trees > 0 && o.vehicles > 0) {
    if (!lay.place_tree_over(first_vehicle, o.vehicles, error)) return false;
    trees = 1;
  }
  for (; trees < o.trees; ++trees) {
    auto make = [&] {
      const Eigen::Vector2d at = lay.random_xy();
      const Eigen::Vector2d shift(rng->uniform(-kFreeCrownShift, kFreeCrownShift),
                                  rng->uniform(-kFreeCrownShift, kFreeCrownShift));
      return make_tree(t, at, at + shift, -INFINITY, rng);
    };
    if (!lay.place("tree", trees, make, error)) return false;
  }
  for (uint32_t c = 0; c < o.crates; ++c) {
    if (!lay.place(
            "crate", c, [&] { return make_crate(t, lay.random_xy(), lay.random_yaw(), rng); }, error))
      return false;
  }
  for (uint32_t u = 0; u < o.unknown_vehicles; ++u) {
    const Mesh& m = unknown[rng->below(static_cast<uint32_t>(unknown.size()))];
    auto make = [&] {
      return place_vehicle(m, SceneObjectKind::kUnknownVehicle, t, lay.random_xy(), lay.random_yaw());
    };
    if (!lay.place("unknown vehicle", u, make, error)) return false;
  }
  // Vehicle-sized clutter last: a tile without it draws as it always did.
  const uint32_t counts[kSizedClutterKinds] = {o.sheds, o.containers, o.bushes, o.heaps};
  for (uint32_t k = 0; k < kSizedClutterKinds; ++k) {
    const SizedClutter& sized = kSizedClutter[k];
    for (uint32_t c = 0; c < counts[k]; ++c) {
      if (!lay.place(
              scene_object_kind_name(sized.kind), c,
              [&] { return sized.make(t, lay.random_xy(), lay.random_yaw(), rng); }, error))
        return false;
    }
  }
  mark_under_trees(out);
  return true;
}

}  // namespace spinhash::host
