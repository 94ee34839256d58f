#include "survey/buffered_source.hpp"

#include "survey/survey_outputs.hpp"

namespace spinhash::survey {

template <class F>
auto BufferedSource::neighbour_named(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const host::CloudError& e) {
    if (next_ <= 1) throw;  // the tile itself: its own message
    // The tile is refused for its neighbour: say so, and which.
    throw host::CloudError("refused for its neighbour " + path_now() +
                           ", which cannot be read: " + without_path(e.what(), path_now()));
  }
}

BufferedSource::BufferedSource(const SurveyTask& task) : task_(task), work_(task.work()) {
  header_.format = "survey";
  header_.count_known = false;
  open_next();
}

bool BufferedSource::open_next() {
  current_.reset();
  if (next_ > task_.neighbours.size()) return false;
  ++next_;
  current_ = neighbour_named([&] { return host::open_metric_source(path_now(), work_, task_.filter); });
  if (next_ == 1) header_.crs = current_->header().crs;
  return true;
}

const std::string& BufferedSource::path_now() const {
  return next_ <= 1 ? task_.tile.path : task_.neighbours[next_ - 2].path;
}

size_t BufferedSource::read(double* xyz, size_t max_points) {
  return neighbour_named([&] { return read_any(xyz, max_points); });
}

size_t BufferedSource::read_any(double* xyz, size_t max_points) {
  while (current_) {
    if (next_ == 1) {  // the tile itself: every point
      const size_t got = current_->read(xyz, max_points);
      tile_points_ += got;
      tile_noise_ = current_->points_noise();
      if (got > 0) return got;
    } else {  // a neighbour: its points inside the seen rectangle
      chunk_.resize(3 * max_points);
      const size_t got = current_->read(chunk_.data(), max_points);
      size_t kept = 0;
      for (size_t i = 0; i < got; ++i) {
        const double* p = chunk_.data() + 3 * i;
        if (p[0] >= task_.seen.min[0] && p[0] < task_.seen.max[0] && p[1] >= task_.seen.min[1] &&
            p[1] < task_.seen.max[1])
          std::copy(p, p + 3, xyz + 3 * kept++);
      }
      buffer_points_ += kept;
      if (kept > 0) return kept;
      if (got > 0) continue;
    }
    open_next();
  }
  return 0;
}

}  // namespace spinhash::survey
