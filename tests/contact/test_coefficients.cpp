// Model "coefficients" (contact/coefficients.cpp) against the formulas written
// out here: Kalker's linear theory on the geometry's C_ij or prescribed f_ij
// (Kalker 1990 App. E), the Shen-Hedrick-Elkins cubic against contact/she.cpp
// on the same coefficients, the validity flags of both laws; and
// find_tangential_model (registry.hpp): names checked without building a model.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "contact/kalker_coefficients.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"

using namespace railsim::contact;

namespace {

constexpr double kG = 8.0e10;  // shear modulus [Pa] of the given coefficients, not the material's

// A patch with the coefficients a contact table would give at it (values of
// Kalker's table near a/b = 0.8, nu = 0.28; any positive numbers would do).
ContactInput table_input(double xi, double eta, double phi) {
  ContactInput in;
  in.patch.a = 6.0e-3;
  in.patch.b = 7.5e-3;
  in.patch.Fz = 80.0e3;
  in.material = Material{210.0e9, 0.28, 0.3};
  in.creep = {xi, eta, phi};
  in.coefficients.C11 = 4.3;
  in.coefficients.C22 = 3.8;
  in.coefficients.C23 = 1.5;
  in.coefficients.C33 = 0.9;
  in.coefficients.shear_modulus = kG;
  return in;
}

std::unique_ptr<TangentialModel> coefficients_model(const char* saturation) {
  TangentialModelOptions o;
  o.saturation = saturation;
  return make_tangential_model("coefficients", o);
}

}  // namespace

TEST_CASE("coefficients, saturation none: Kalker's linear theory on the geometry's C_ij", "[contact][coefficients]") {
  const auto model = coefficients_model("none");
  CHECK_FALSE(model->coulomb_bounded());
  for (const double phi : {0.0, 0.05, -0.08}) {
    ContactInput in = table_input(2e-5, -3e-5, phi);
    in.reduction = {0.9, 0.7, 0.5};
    const ContactForces f = model->solve(in);
    const double ab = in.patch.a * in.patch.b, c = std::sqrt(ab);
    const double f11 = kG * ab * 4.3 * 0.9, f22 = kG * ab * 3.8 * 0.7, f23 = kG * ab * c * 1.5 * 0.5,
                 f33 = kG * ab * ab * 0.9 * 0.5;
    CHECK(f.Fx == Approx(-f11 * 2e-5).epsilon(1e-13));
    CHECK(f.Fy == Approx(f22 * 3e-5 - f23 * phi).epsilon(1e-13));
    CHECK(f.Mz == Approx(-f23 * 3e-5 - f33 * phi).epsilon(1e-13));
    CHECK(f.valid);  // small creepage: |F| well below 0.3 mu Fz
  }
  // Beyond small creepage the law is still linear and says so.
  const ContactForces big = model->solve(table_input(3e-3, 0.0, 0.0));
  CHECK(big.Fx == Approx(-kG * 6.0e-3 * 7.5e-3 * 4.3 * 3e-3).epsilon(1e-13));
  CHECK(std::abs(big.Fx) > 0.3 * 0.3 * 80.0e3);
  CHECK_FALSE(big.valid);
  CHECK(std::string(big.reason).find("small creepage") != std::string::npos);
}

TEST_CASE("coefficients: prescribed f_ij scale with the load as Hertz, without a patch", "[contact][coefficients]") {
  const auto model = coefficients_model("none");
  ContactInput in;
  in.patch.Fz = 2.0 * 55.0e3;  // twice the reference load; no patch (conical wheels)
  in.material = Material{210.0e9, 0.28, 0.3};
  in.creep = {1e-5, 2e-5, 0.01};
  in.coefficients = {0, 0, 0, 0, 1.0e7, 0.9e7, 1.0e4, 20.0, 55.0e3, 0.0};
  const ContactForces f = model->solve(in);
  const double r23 = std::pow(2.0, 2.0 / 3.0), r43 = std::pow(2.0, 4.0 / 3.0);
  CHECK(f.Fx == Approx(-1.0e7 * r23 * 1e-5).epsilon(1e-13));
  CHECK(f.Fy == Approx(-0.9e7 * r23 * 2e-5 - 1.0e4 * 2.0 * 0.01).epsilon(1e-13));
  CHECK(f.Mz == Approx(1.0e4 * 2.0 * 2e-5 - 20.0 * r43 * 0.01).epsilon(1e-13));
  // Neither coefficients nor a patch: no creep force (DYTSI's contact without a patch).
  in.coefficients = {};
  const ContactForces z = model->solve(in);
  CHECK(z.Fx == 0.0);
  CHECK(z.Fy == 0.0);
  CHECK(z.Mz == 0.0);
  // A prescribed set needs its reference load.
  in.coefficients.f11 = 1.0e7;
  CHECK_THROWS_WITH(model->solve(in), Catch::Contains("Fz_ref"));
}

TEST_CASE("coefficients on a bare patch: Kalker's table at a/b, as the models linear and she",
          "[contact][coefficients]") {
  // No coefficients given: the same numbers as the registry's own models
  // (which take Kalker's C_ij at the patch's a/b), to rounding.
  for (const char* law : {"none", "she"}) {
    const auto model = coefficients_model(law);
    const auto ref = make_tangential_model(std::string(law) == "none" ? "linear" : "she");
    for (const double s : {1e-4, 1e-3, 5e-3})
      for (const double phi : {0.0, 0.4, -2.0}) {
        ContactInput in = table_input(s, -0.7 * s, phi);
        in.coefficients = {};
        const ContactForces f = model->solve(in), g = ref->solve(in);
        const double muN = in.material.mu * in.patch.Fz;
        INFO(law << " s " << s << " phi " << phi);
        CHECK(std::abs(f.Fx - g.Fx) <= 1e-12 * muN);
        CHECK(std::abs(f.Fy - g.Fy) <= 1e-12 * muN);
        CHECK(std::abs(f.Mz - g.Mz) <= 1e-12 * muN * in.patch.b);
        CHECK(f.valid == g.valid);
      }
  }
}

TEST_CASE("coefficients, saturation she: the SHE cubic of contact/she.cpp on the geometry's coefficients",
          "[contact][coefficients][she]") {
  const auto model = coefficients_model("she");
  CHECK(model->coulomb_bounded());
  const auto she = make_tangential_model("she");
  for (const double s : {1e-5, 1e-4, 5e-4, 2e-3, 1e-2})
    for (const double phi : {0.0, 0.3, -0.6}) {
      ContactInput in = table_input(s, 0.5 * s, phi);
      const ContactForces f = model->solve(in);
      // Independent: linear forces on the given coefficients, u = |F_lin| / (mu Fz),
      // |F| = mu Fz (u - u^2/3 + u^3/27) for u < 3, mu Fz beyond; direction and Mz scaled alike.
      const double ab = in.patch.a * in.patch.b, c = std::sqrt(ab), muN = 0.3 * 80.0e3;
      const double Fx = -kG * ab * 4.3 * s, Fy = -kG * ab * 3.8 * 0.5 * s - kG * ab * c * 1.5 * phi;
      const double Mz = kG * ab * c * 1.5 * 0.5 * s - kG * ab * ab * 0.9 * phi;
      const double u = std::hypot(Fx, Fy) / muN;
      const double k = (u < 3.0 ? muN * (u - u * u / 3.0 + u * u * u / 27.0) : muN) / std::hypot(Fx, Fy);
      INFO("s " << s << " phi " << phi << " u " << u);
      CHECK(std::abs(f.Fx - k * Fx) <= 1e-12 * muN);
      CHECK(std::abs(f.Fy - k * Fy) <= 1e-12 * muN);
      CHECK(std::abs(f.Mz - k * Mz) <= 1e-12 * muN * in.patch.b);
      // contact/she.cpp given the same coefficients: she takes Kalker's C_ij at
      // the patch's a/b and the material's G, so the geometry gives those.
      ContactInput same = in;
      const KalkerCoefficients C = kalker_coefficients(in.patch.a / in.patch.b, in.material.nu);
      same.coefficients = {C.C11, C.C22, C.C23, C.C33, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      const ContactForces g = she->solve(same), h = model->solve(same);
      CHECK(g.valid == h.valid);
      CHECK(std::abs(g.Fx - h.Fx) <= 1e-12 * muN);
      CHECK(std::abs(g.Fy - h.Fy) <= 1e-12 * muN);
      CHECK(std::abs(g.Mz - h.Mz) <= 1e-12 * muN * in.patch.b);
    }
}

TEST_CASE("coefficients, saturation she: flagged at large spin, as she", "[contact][coefficients][she][validity]") {
  const auto model = coefficients_model("she");
  const double muN = 0.3 * 80.0e3;
  const double f23 = kG * std::pow(6.0e-3 * 7.5e-3, 1.5) * 1.5;
  // psi = |f23 phi| / (mu Fz): 0.1 passes, 0.5 is flagged (limit 0.3).
  const ContactForces small = model->solve(table_input(0.0, 0.0, 0.1 * muN / f23));
  CHECK(small.valid);
  const ContactForces large = model->solve(table_input(0.0, 0.0, 0.5 * muN / f23));
  CHECK_FALSE(large.valid);
  CHECK(std::string(large.reason).find("large spin") != std::string::npos);
  // Large creepage without spin saturates at mu Fz and stays valid.
  const ContactForces sat = model->solve(table_input(0.05, 0.0, 0.0));
  CHECK(std::abs(sat.Fx) == Approx(muN).epsilon(1e-12));
  CHECK(sat.valid);
}

TEST_CASE("coefficients: the saturation law is checked when the model is built", "[contact][coefficients][input]") {
  TangentialModelOptions o;
  o.saturation = "cubic";
  CHECK_THROWS_AS(make_tangential_model("coefficients", o), railsim::InputError);
  CHECK_THROWS_WITH(make_tangential_model("coefficients", o),
                    Catch::Contains("'cubic'") && Catch::Contains("none, she"));
  CHECK(saturation_law_names() == "none, she");
  CHECK(std::string(find_saturation_law("she").description).find("Shen-Hedrick-Elkins") != std::string::npos);
}

TEST_CASE("find_tangential_model: every registered name, unknown names listed, nothing built",
          "[contact][registry]") {
  for (const auto& e : tangential_models()) CHECK(&find_tangential_model(e.name) == &e);
  CHECK(find_tangential_model("coefficients").geometry_coefficients);
  CHECK_FALSE(find_tangential_model("coefficients").compared_by_default());
  CHECK(find_tangential_model("mim_table").tabulated);
  CHECK(find_tangential_model("chopaya").compared_by_default());
  try {
    find_tangential_model("magic");
    FAIL("no exception for an unknown name");
  } catch (const railsim::InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("'magic'") != std::string::npos);
    for (const auto& m : tangential_models()) CHECK(what.find(m.name) != std::string::npos);
  }
  // mim_table checked by name: its cache folder stays empty (building the
  // model would load or build its table there).
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("railsim_find_model_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const char* old = std::getenv("RAILSIM_CACHE_DIR");
  const std::string saved = old ? old : "";
  ::setenv("RAILSIM_CACHE_DIR", dir.c_str(), 1);
  CHECK(std::string(find_tangential_model("mim_table").name) == "mim_table");
  CHECK(fs::is_empty(dir));
  if (old)
    ::setenv("RAILSIM_CACHE_DIR", saved.c_str(), 1);
  else
    ::unsetenv("RAILSIM_CACHE_DIR");
  fs::remove_all(dir);
}
