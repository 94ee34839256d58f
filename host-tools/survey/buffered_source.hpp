// A tile with its neighbours' buffer as one point source, in metres of the
// survey's CRS (cloud/metric_source.hpp: each file scaled by its own units,
// or reprojected): the tile's points, then each neighbour's points inside
// the seen rectangle, neighbours in path order, each opened only while it
// is read (memory: one reader's chunk).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "cloud/metric_source.hpp"
#include "survey/task.hpp"

namespace spinhash::survey {

class BufferedSource final : public host::PointSource {
 public:
  explicit BufferedSource(const SurveyTask& task);
  const host::CloudHeader& header() const override { return header_; }
  // Throws host::CloudError naming the file: the tile's own error, or
  // "refused for its neighbour PATH, which cannot be read: ...".
  size_t read(double* xyz, size_t max_points) override;

  uint64_t tile_points() const { return tile_points_; }
  uint64_t buffer_points() const { return buffer_points_; }
  // The tile's own points that its file marks as noise or withheld.
  uint64_t points_noise() const override { return tile_noise_; }

 private:
  bool open_next();
  size_t read_any(double* xyz, size_t max_points);
  const std::string& path_now() const;  // the file being read
  template <class F>
  auto neighbour_named(F&& f) -> decltype(f());

  const SurveyTask& task_;
  host::WorkCrs work_;
  host::CloudHeader header_;
  std::unique_ptr<host::PointSource> current_;
  size_t next_ = 0;  // 0: the tile; k: neighbour k - 1
  std::vector<double> chunk_;
  uint64_t tile_points_ = 0, buffer_points_ = 0, tile_noise_ = 0;
};

}  // namespace spinhash::survey
