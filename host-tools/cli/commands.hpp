// The spinhash subcommands. Each registers itself on the app and, when
// chosen, stores its exit status in *exit_code:
//   kExitOk, kExitError or kExitCheckFailed (pipeline/exit_codes.hpp).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cloud/metric_source.hpp"
#include "pipeline/exit_codes.hpp"

namespace spinhash::cli {

using pipeline::kExitCheckFailed;
using pipeline::kExitError;
using pipeline::kExitOk;

// Clouds named on a command line may include "-" (stdin) once: a second is a
// usage error (CLI::ValidationError, exit 2), as stdin can be read only once.
void refuse_repeated_stdin(const std::vector<std::string>& clouds);

// --work-crs CRS: a projected CRS to work in (EPSG:n, a WKT or a PROJ
// string); files in another CRS, or in degrees, are reprojected into it. A
// CRS PROJ does not read, or one in degrees, is a usage error (exit 2).
void add_work_crs_option(CLI::App* cmd, host::WorkCrs* work);

// --drop-class N[,N...]: LAS classes the readers leave out besides noise
// and withheld points (cloud/point_filter.hpp). A value that is not a class
// is a usage error (exit 2). Repeatable.
void add_drop_class_option(CLI::App* cmd, host::PointFilter* filter);

// --order-memory POINTS: the points a tile's along-track order holds in
// memory before it spills to a temporary file (pipeline/tile_stream_order.hpp).
void add_order_memory_option(CLI::App* cmd, size_t* points);

// A message of one or more lines on stderr, each as "spinhash COMMAND: line".
void print_error(const char* command, const std::string& message);

void add_build_command(CLI::App& app, int* exit_code);
void add_info_command(CLI::App& app, int* exit_code);
void add_verify_command(CLI::App& app, int* exit_code);
void add_scan_command(CLI::App& app, int* exit_code);
void add_recognize_command(CLI::App& app, int* exit_code);
void add_generate_command(CLI::App& app, int* exit_code);
void add_scene_command(CLI::App& app, int* exit_code);
void add_scan_scene_command(CLI::App& app, int* exit_code);
void add_survey_command(CLI::App& app, int* exit_code);

}  // namespace spinhash::cli
