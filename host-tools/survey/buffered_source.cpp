#include "survey/buffered_source.hpp"

namespace spinhash::survey {

BufferedSource::BufferedSource(const SurveyTask& task) : task_(task), work_(task.work()) {
  header_.format = "survey";
  header_.count_known = false;
  open_next();
}

bool BufferedSource::open_next() {
  current_.reset();
  if (next_ > task_.neighbours.size()) return false;
  const std::string& path = next_ == 0 ? task_.tile.path : task_.neighbours[next_ - 1].path;
  ++next_;
  current_ = host::open_metric_source(path, work_);
  if (next_ == 1) header_.crs = current_->header().crs;
  return true;
}

size_t BufferedSource::read(double* xyz, size_t max_points) {
  while (current_) {
    if (next_ == 1) {  // the tile itself: every point
      const size_t got = current_->read(xyz, max_points);
      tile_points_ += got;
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
