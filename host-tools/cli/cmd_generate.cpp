// spinhash generate -o DIR: procedural look-alike vehicles (built-in data).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "mesh/mesh_writer.hpp"
#include "mesh/vehicle_generator.hpp"

namespace spinhash::cli {
namespace {

struct GenerateArgs {
  std::string output;
  uint32_t count = 56;
  uint64_t seed = 1;
  std::string format = "obj";
};

int run_generate(const GenerateArgs& a) {
  std::error_code ec;
  std::filesystem::create_directories(a.output, ec);
  if (ec) {
    std::fprintf(stderr, "spinhash generate: %s: %s\n", a.output.c_str(), ec.message().c_str());
    return kExitError;
  }
  std::vector<host::Mesh> fleet = host::generate_fleet(a.count, a.seed);
  for (const host::Mesh& m : fleet) {
    std::string path = (std::filesystem::path(a.output) / (m.name + "." + a.format)).string();
    std::string error;
    bool ok = a.format == "obj" ? host::write_obj(path, m, &error) : host::write_mesh_ply(path, m, &error);
    if (!ok) {
      std::fprintf(stderr, "spinhash generate: %s: %s\n", path.c_str(), error.c_str());
      return kExitError;
    }
  }
  std::fprintf(stderr, "spinhash generate: %zu vehicles in %s\n", fleet.size(), a.output.c_str());
  return kExitOk;
}

}  // namespace

void add_generate_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<GenerateArgs>();
  CLI::App* cmd = app.add_subcommand("generate", "write procedural vehicle meshes (families of look-alikes)");
  cmd->add_option("-o,--output", a->output, "directory to write into")->required();
  cmd->add_option("--count", a->count, "number of vehicles")
      ->check(CLI::Range(1u, host::kMaxFleetSize))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "fleet seed")->capture_default_str();
  cmd->add_option("--format", a->format, "mesh format")
      ->check(CLI::IsMember({"obj", "ply"}))
      ->capture_default_str();
  cmd->callback([a, exit_code]() { *exit_code = run_generate(*a); });
}

}  // namespace spinhash::cli
