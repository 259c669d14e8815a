// `railsim version`: the program version, the versions of its dependencies and
// the data folder it reads (core/data_dir.hpp).
#include <Eigen/Core>
#include <boost/version.hpp>
#include <fftw3.h>
#include <spdlog/spdlog.h>
#include <spdlog/version.h>
#include <sundials/sundials_config.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>

#include "cli/commands.hpp"
#include "core/data_dir.hpp"
#include "core/version.hpp"
#ifndef RAILSIM_YAMLCPP_VERSION
#define RAILSIM_YAMLCPP_VERSION "unknown"
#endif

namespace railsim::cli {

void register_version(CLI::App& app, CommandRunner& run) {
  auto* cmd = app.add_subcommand("version", "Print the railsim version and dependency versions");
  cmd->callback([&run] {
    run = [] {
      std::printf("railsim %s\n", railsim::kVersion);
      std::printf("  compiler      %s\n", __VERSION__);
      std::printf("  Eigen         %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
      std::printf("  SUNDIALS      %s\n", SUNDIALS_VERSION);
      std::printf("  Boost         %d.%d.%d\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000,
                  BOOST_VERSION % 100);
      std::printf("  yaml-cpp      %s\n", RAILSIM_YAMLCPP_VERSION);
      std::printf("  spdlog        %d.%d.%d\n", SPDLOG_VER_MAJOR, SPDLOG_VER_MINOR, SPDLOG_VER_PATCH);
      std::printf("  CLI11         %s\n", CLI11_VERSION);
      std::printf("  FFTW          %s\n", fftw_version);
#ifdef RAILSIM_HAVE_MPI
      std::printf("  MPI           yes\n");
#else
      std::printf("  MPI           not found at build time\n");
#endif
      const std::string data = find_data_dir();
      std::printf("  data folder   %s\n", data.empty() ? "not found (set RAILSIM_DATA_DIR)" : data.c_str());
      return 0;
    };
  });
}

}  // namespace railsim::cli
