// Data folder resolution; see data_dir.hpp.
#include "core/data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

#include "core/errors.hpp"

namespace railsim {

namespace fs = std::filesystem;

namespace {
constexpr const char* kMarker = "railsim-data.txt";
constexpr int kParents = 4;

bool is_data_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p / kMarker, ec);
}
}  // namespace

std::string binary_path() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&binary_path), &info) != 0 && info.dli_fname && *info.dli_fname) {
    std::error_code ec;
    const fs::path p = fs::canonical(info.dli_fname, ec);
    if (!ec) return p.string();
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.string();
}

std::string find_data_dir() {
  if (const char* e = std::getenv("RAILSIM_DATA_DIR"); e && *e) return e;
  const std::string bin = binary_path();
  if (bin.empty()) return {};
  fs::path dir = fs::path(bin).parent_path();
  for (int i = 0; i <= kParents && !dir.empty(); ++i) {
    const fs::path candidate = dir / "share" / "railsim";
    if (is_data_dir(candidate)) return candidate.string();
    if (dir == dir.root_path()) break;
    dir = dir.parent_path();
  }
  return {};
}

std::string data_dir() {
  if (const char* e = std::getenv("RAILSIM_DATA_DIR"); e && *e) {
    if (!is_data_dir(e))
      throw InputError(std::string("RAILSIM_DATA_DIR=") + e + ": not a railsim data folder (no " + kMarker +
                       " in it); unset it to use the data installed with railsim");
    return e;
  }
  const std::string d = find_data_dir();
  if (d.empty())
    throw InputError("railsim data folder not found: looked for share/railsim/" + std::string(kMarker) +
                     " beside and up to " + std::to_string(kParents) + " folders above " + binary_path() +
                     "; set RAILSIM_DATA_DIR to the folder holding profiles/, plots/, vehicles/, tracks/ and scenarios/");
  return d;
}

std::string data_path(const std::string& relative) { return data_dir() + "/" + relative; }

}  // namespace railsim
