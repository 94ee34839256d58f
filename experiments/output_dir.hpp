// The experiments' output folder and its text files.
#pragma once
#include <string>

namespace spinhash::experiment {

// Where an experiment writes when --out is not given: out/NAME under the
// working folder. From the source tree's root that is out/, which git
// ignores: results stay out of the sources unless copied in on purpose.
std::string default_output_dir(const std::string& experiment);
bool make_output_dir(const std::string& dir, std::string* error);
bool write_text(const std::string& path, const std::string& text, std::string* error);
// This process's command line (Linux /proc/self/cmdline; arguments with
// spaces quoted), for the summaries; empty where unavailable.
std::string invoked_command_line();

}  // namespace spinhash::experiment
