#include <algorithm>
#include <cstdio>

#include "cli/commands.hpp"
#include "cloud/crs_resolve.hpp"
#include "pipeline/tile_stream_order.hpp"

namespace spinhash::cli {

void refuse_repeated_stdin(const std::vector<std::string>& clouds) {
  if (std::count(clouds.begin(), clouds.end(), host::kStdinPath) > 1)
    throw CLI::ValidationError("clouds", "'-' (stdin) named more than once: stdin can be read only once");
}

void add_order_memory_option(CLI::App* cmd, size_t* points) {
  cmd->add_option("--order-memory", *points,
                  "points of a tile held in memory (12 B each) while it is put in along-track order; the "
                  "rest wait in a temporary file; answers do not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(pipeline::kMinOrderMemoryPoints, pipeline::kMaxOrderMemoryPoints));
}

void add_work_crs_option(CLI::App* cmd, host::WorkCrs* work) {
  cmd->add_option_function<std::string>(
         "--work-crs",
         [work](const std::string& text) {
           std::string error;
           if (!host::crs_from_user(text, &work->crs, &error))
             throw CLI::ValidationError("--work-crs", error);
           if (work->crs.units.geographic)
             throw CLI::ValidationError("--work-crs",
                                        text + " is in degrees: name a projected CRS (metres or feet)");
           work->named = true;
         },
         "a projected CRS to work in (EPSG:n, WKT or PROJ string): files in another CRS, or in degrees, are "
         "reprojected into it; outputs are in it")
      ->type_name("CRS");
}

void add_drop_class_option(CLI::App* cmd, host::PointFilter* filter) {
  cmd->add_option_function<std::vector<std::string>>(
         "--drop-class",
         [filter](const std::vector<std::string>& lists) {
           for (const std::string& list : lists) {
             std::string error;
             if (!host::add_drop_classes(list, filter, &error))
               throw CLI::ValidationError("--drop-class", error);
           }
         },
         "LAS classes to leave out besides noise (7, 18) and withheld points, e.g. a producer's own artefact "
         "class: N or N,N,... (LAS and LAZ)")
      ->type_name("CLASSES")
      ->take_all();
}

void print_error(const char* command, const std::string& message) {
  for (size_t start = 0; start <= message.size();) {
    size_t end = message.find('\n', start);
    if (end == std::string::npos) end = message.size();
    std::fprintf(stderr, "spinhash %s: %s\n", command, message.substr(start, end - start).c_str());
    start = end + 1;
  }
}

}  // namespace spinhash::cli
