// Cached table of exact (MIM) creep forces, looked up by smooth interpolation:
// the tangential model "mim_table".
//
// Idea: Kalker's TABCON/USETAB tables as produced by CONTACT's usetab_table
// (physics-reference.md section 11). For a Hertzian patch with Coulomb
// friction the exact steady-rolling solution depends only on a/b, nu and the
// normalised creepages
//   xi'  = G c^2 C11 xi  / (3 mu N),   eta' = G c^2 C22 eta / (3 mu N),
//   psi' = G c^3 C23 phi / (mu N)      (c = sqrt(ab), C_ij at the table's nu),
// and gives Fx/(mu N), Fy/(mu N), Mz/(mu N c). Reduction factors act on the
// normalisation (C_ij -> k_ij C_ij; C33 follows k23).
// Lateral axis: the table is laid out over e' = eta' + psi'/3 instead of
// eta'. In these units the linear theory gives Fy/(mu N) = -3 e', so e' is the
// combined (creepage + spin) lateral creepage and Fy changes sign near e' = 0
// when lateral creepage opposes spin; over (eta', psi') that sign change is a
// steep diagonal ridge that cubic interpolation between nodes missed by up to
// 4 % of mu N (7 % against CONTACT, issue 15), over (e', psi') it is a gentle
// slope along e'.
// Symmetries used (exact for the half-space problem, w = (xi - phi y, eta + phi x)):
//   (-xi, eta, phi) -> (-Fx, Fy, Mz);   (xi, -eta, -phi) -> (Fx, -Fy, -Mz),
// so the table holds xi' >= 0, e' >= 0 and psi' of both signs.
//
// Axes (all stored in the file): ln(a/b); u(xi') and u(e') with
// u(s) = s / (1 + s) in [0, 1) (uniform in u: dense near zero, reaching far
// into saturation); v(psi') = psi' / (1 + |psi'|). Beyond the last node a value
// is held (full slip: the forces no longer change much). Interpolation: cubic
// Hermite with finite-difference slopes in each axis (C1, exact at the nodes),
// tensor product of 4 x 4 x 4 x 4 nodes, no allocation. The interpolated
// force can overshoot mu N slightly between nodes; the Coulomb law of the
// model interface (coulomb_bound.hpp) limits it.
//
// File (little-endian binary): magic "RSMIMTAB", format version, solver id,
// nu, grid, tolerance, axis nodes, values, and a 64-bit FNV-1a hash of all
// preceding bytes. A file that is truncated, corrupt (hash), of another format
// version, another solver id, or built for other parameters is refused with a
// message saying why (MimTable::load throws InputError); the model then
// rebuilds it. Building runs on threads and appends each finished node to
// "<file>.partial" (record = index + 3 values + checksum), so an interrupted
// build resumes from the valid records; the final file is written to a
// temporary name and renamed, so it is never seen half-written.
//
// Files, one job each: mim_table/spec.cpp (standard table, checks, parameter
// hash), mim_table/file.cpp (binary format), mim_table/lookup.cpp (Hermite
// interpolation), mim_table/build.cpp (threaded resumable build),
// mim_table/cache.cpp (cache folder and file, load-or-build under the file
// lock of core/file_lock.hpp), mim_table/model.cpp (the model "mim_table");
// internal: mim_table/bytes.hpp (byte writer/reader), mim_table/axes.hpp
// (axis maps).
//
// Units: SI; signs as contact/types.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "contact/registry.hpp"
#include "contact/tangential_model.hpp"

namespace railsim::contact {

// Solver identity written into tables; bump when the MIM solver's results change.
// 3: the registered "mim" with Richardson extrapolation from the grid and the half grid.
inline constexpr const char* kMimTableSolverId = "railsim-mim-steady-hertz-richardson-3";
inline constexpr std::uint32_t kMimTableFormatVersion = 2;  // 2: lateral axis e' = eta' + psi'/3

struct MimTableSpec {
  std::vector<double> aob;  // a/b nodes (ascending, > 0)
  std::vector<double> uxi;  // u(xi') nodes in [0, 1), ascending, first 0
  std::vector<double> ueta; // u(e') nodes in [0, 1), ascending, first 0; e' = eta' + psi'/3
  std::vector<double> vpsi; // v(psi') nodes in (-1, 1), ascending
  double nu = 0.28;         // Poisson's ratio of the table
  int grid = 28;            // MIM elements across the minor axis
  double tolerance = 1e-6;  // MIM tangential tolerance

  // The default table: 9 shapes a/b in [0.2, 5], 13 x 13 creepage nodes, 37
  // spin nodes, MIM grid 28 extrapolated from 28 and 14 (56,277 solves).
  // Measured on railsim's exact reference set (tests/data/contact/spin_reference):
  // 0.55 % of mu N max, 0.14 % mean (without the extrapolation 1.6 % against
  // plain grid 120, 2.1 % against the extrapolated reference); README.md. (9 x 9 x 19 nodes at grid 20: 5.2 % of mu N; grid 20 alone
  // is 1.9 % off, the interpolation 4.0 %, 2.3 % over e'.)
  static MimTableSpec standard();
  std::size_t size() const { return aob.size() * uxi.size() * ueta.size() * vpsi.size(); }
  // Throws InputError when the axes are not usable (sizes, order, ranges).
  void check() const;
  // Hash of the parameters (names the cache file).
  std::uint64_t hash() const;
};

struct MimTableBuildOptions {
  int threads = 0;  // 0 = hardware concurrency
  // Progress callback (done, total), called from the building threads (serialised).
  std::function<void(std::size_t, std::size_t)> progress;
  // Stop after this many new nodes (testing an interrupted build); 0 = no limit.
  std::size_t stop_after = 0;
};

class MimTable {
 public:
  // Build with the live MIM solver; `partial_path` (may be empty) is the resume log.
  // Returns nullptr when stopped early by options.stop_after.
  static std::unique_ptr<MimTable> build(const MimTableSpec& spec, const std::string& partial_path,
                                         const MimTableBuildOptions& options = {});
  // Load and verify; throws InputError naming the file and the reason
  // (truncated, corrupt, other version/solver, other parameters).
  static std::unique_ptr<MimTable> load(const std::string& path, const MimTableSpec& expected);
  // Write atomically (temporary file + rename). Throws InputError on I/O failure.
  void save(const std::string& path) const;

  const MimTableSpec& spec() const { return spec_; }
  // Normalised forces (Fx, Fy)/(mu N), Mz/(mu N c) at a/b and normalised
  // creepages xi' >= 0, e' = eta' + psi'/3 >= 0, psi'.
  void lookup(double aob, double xi_n, double e_n, double psi_n, double out[3]) const;
  // Value stored at a node (indices along aob, uxi, ueta, vpsi).
  const double* node(std::size_t i, std::size_t j, std::size_t k, std::size_t l) const;

 private:
  MimTableSpec spec_;
  std::vector<double> lnaob_;  // ln(a/b) nodes
  std::vector<double> values_; // 3 per node, index ((i * nj + j) * nk + k) * nl + l
};

// Exact normalised forces at one table node, from a live MIM solve on a
// reference patch (used to build tables and by tests).
void mim_table_reference(const MimTableSpec& spec, double aob, double xi_n, double eta_n, double psi_n,
                         double out[3]);

// The cache folder: `configured` if not empty, else $RAILSIM_CACHE_DIR, else
// $XDG_CACHE_HOME/railsim, else $HOME/.cache/railsim (created when missing).
std::string mim_table_cache_dir(const std::string& configured);
// The file that holds the table for `spec` in that cache folder (it may not exist).
std::string mim_table_cache_path(const MimTableSpec& spec, const std::string& configured_cache_dir);

class MimTableModel final : public TangentialModel {
 public:
  explicit MimTableModel(std::shared_ptr<const MimTable> table) : table_(std::move(table)) {}
  std::string_view name() const override { return "mim_table"; }
  ContactForces compute(const ContactInput& in, TangentialWorkspace* ws) const override;
  const MimTable& table() const { return *table_; }

 private:
  std::shared_ptr<const MimTable> table_;
};

// Load the table for `spec` from `cache_dir` (see mim_table_cache_dir), or
// build and store it when missing or refused (the reason is reported through
// `log`, progress too).
std::shared_ptr<const MimTable> load_or_build_mim_table(const MimTableSpec& spec, const std::string& cache_dir,
                                                        const std::function<void(const std::string&)>& log);

// Registry factory: options.cache_dir; options.grid / tolerance override the
// MIM settings of the standard table.
std::unique_ptr<TangentialModel> make_mim_table(const TangentialModelOptions& options);

}  // namespace railsim::contact
