// Python bindings of the contact models: every registered tangential model on
// numpy arrays (the loop in C++ with the GIL released, the model and its
// workspace built once per call), and the exact MIM solver's fields.
//
// Inputs are 1-D float64 arrays of one common length n, or of length 1 (the
// value holds for every point); the Python wrapper railsim.contact() broadcasts
// scalars and shapes. Per point: the Hertz patch from the semi-axes a, b
// (hertz_from_semi_axes) or the curvatures A, B (hertz_from_load) and the load
// Fz, for material E, nu, mu, exactly as `railsim contact` does for a case
// file; it is recomputed only when the patch data change from the previous
// point. Outputs: Fx, Fy, Mz [N, N m] (forces of the rail on the wheel,
// contact/types.hpp), valid, iterations, stick_fraction, the patch a, b, p0
// (numbers when the patch data are one value each, else arrays),
// and per point the index of its validity reason in reason_texts (0: valid).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/mim/mim_model.hpp"
#include "contact/reduction.hpp"
#include "contact/registry.hpp"
#include "core/errors.hpp"
#include "python/src/bindings.hpp"

namespace py = pybind11;

namespace railsim::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A read-only view of an input array of length n or 1 (stride 0: one value for all).
struct Column {
  const double* p = nullptr;
  py::ssize_t n = 0;
  py::ssize_t stride = 1;
  double operator[](py::ssize_t i) const { return p[i * stride]; }
};

Column column(const Array& a, const char* name, py::ssize_t& n) {
  if (a.ndim() != 1) throw InputError(std::string(name) + ": expected a 1-D array");
  const py::ssize_t len = a.shape(0);
  if (len == 0) throw InputError(std::string(name) + ": empty array");
  if (len != 1) {
    if (n > 1 && len != n)
      throw InputError(std::string(name) + ": length " + std::to_string(len) + " differs from the other arrays' " +
                       std::to_string(n));
    n = len;
  }
  return {a.data(), len, len == 1 ? 0 : 1};
}

// Every value of a column within [lo, hi] (open ends where asked), the ranges
// of `railsim contact`'s case files (cli/support_contact_cases.cpp); an
// InputError names the argument, the index and the admissible range.
void check_range(const Column& c, const char* name, double lo, double hi, bool lo_open = false,
                 bool hi_open = false, const char* unit = "") {
  for (py::ssize_t i = 0; i < c.n; ++i) {
    const double v = c.p[i];
    const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
    if (ok) continue;
    std::ostringstream m;
    m << name;
    if (c.n > 1) m << "[" << i << "]";
    m << " = " << v << ": expected ";
    if (lo == -std::numeric_limits<double>::max() && hi == std::numeric_limits<double>::max())
      m << "a finite number";
    else
      m << "a value in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    m << unit;
    throw InputError(m.str());
  }
}

Column one(const double& v) { return Column{&v, 1, 0}; }

// The Hertz patch of one point with the ranges of `railsim contact`'s case
// files: Fz, E, nu, the curvatures or semi-axes given, and the semi-axes of
// the patch the curvatures give, in [1e-6, 1] m.
// The Hertz patch's data (per point or one value): the curvatures or the
// semi-axes, the load and the material's E and nu.
void check_patch_data(bool curvatures, const Column& s1, const Column& s2, const Column& Fz, const Column& E,
                      const Column& nu) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  if (curvatures) {
    check_range(s1, "A", 0.0, kHuge, true, false, " 1/m");
    check_range(s2, "B", 0.0, kHuge, true, false, " 1/m");
  } else {
    check_range(s1, "a", 1e-6, 1.0, false, false, " m");
    check_range(s2, "b", 1e-6, 1.0, false, false, " m");
  }
  check_range(Fz, "Fz", 0.0, 1e7, true, false, " N");
  check_range(E, "E", 1e9, 1e13, false, false, " Pa");
  check_range(nu, "nu", 0.0, 0.5, false, true);
}

contact::HertzPatch checked_hertz_patch(double s1, double s2, bool curvatures, double Fz,
                                        const contact::Material& m) {
  check_patch_data(curvatures, one(s1), one(s2), one(Fz), one(m.E), one(m.nu));
  const contact::HertzPatch p =
      curvatures ? contact::hertz_from_load(s1, s2, Fz, m) : contact::hertz_from_semi_axes(s1, s2, Fz, m);
  if (curvatures) {
    check_range(one(p.a), "the patch's semi-axis a (from A, B and Fz)", 1e-6, 1.0, false, false, " m");
    check_range(one(p.b), "the patch's semi-axis b (from A, B and Fz)", 1e-6, 1.0, false, false, " m");
  }
  return p;
}

py::dict solve_arrays(const std::string& model_name, bool curvatures, const Array& xi, const Array& eta,
                      const Array& phi, const Array& s1, const Array& s2, const Array& fz, const Array& e,
                      const Array& nu, const Array& mu, const Array& v, const Array& k11, const Array& k22,
                      const Array& k23, int grid, double tolerance, const std::string& cache_dir,
                      const std::string& extrapolation) {
  contact::TangentialModelOptions mo;
  mo.grid = grid;
  mo.tolerance = tolerance;
  mo.extrapolation = contact::grid_extrapolation_from_name(extrapolation, "contact");
  mo.cache_dir = cache_dir;
  const contact::TangentialModelEntry& entry = contact::find_tangential_model(model_name);
  for (const contact::TangentialOption flag : contact::unused_model_options(entry, mo))
    throw InputError(std::string(contact::option_field_name(flag)) + ": model '" + model_name +
                     "' does not use it (models that do: " + contact::models_reading(flag) + ")");
  const auto model = contact::make_tangential_model(model_name, mo);
  const auto ws = model->make_workspace();

  py::ssize_t n = 1;
  const Column cx = column(xi, "xi", n), ce = column(eta, "eta", n), cp = column(phi, "phi", n);
  const Column c1 = column(s1, curvatures ? "A" : "a", n), c2 = column(s2, curvatures ? "B" : "b", n);
  const Column cf = column(fz, "Fz", n), cE = column(e, "E", n), cnu = column(nu, "nu", n), cmu = column(mu, "mu", n);
  const Column cv = column(v, "V", n), ck1 = column(k11, "k11", n), ck2 = column(k22, "k22", n),
               ck3 = column(k23, "k23", n);

  constexpr double kHuge = std::numeric_limits<double>::max();
  check_range(cx, "xi", -kHuge, kHuge);
  check_range(ce, "eta", -kHuge, kHuge);
  check_range(cp, "phi", -kHuge, kHuge, false, false, " 1/m");
  check_patch_data(curvatures, c1, c2, cf, cE, cnu);
  check_range(cmu, "mu", 0.0, 2.0, true);
  check_range(cv, "V", 0.0, 200.0, false, false, " m/s");
  check_range(ck1, "k11", 0.0, 1.5, true);
  check_range(ck2, "k22", 0.0, 1.5, true);
  check_range(ck3, "k23", 0.0, 1.5, true);

  // One patch for all points: a, b, p0 come back as numbers, else as arrays.
  const bool fixed_patch = c1.n == 1 && c2.n == 1 && cf.n == 1 && cE.n == 1 && cnu.n == 1;
  const py::ssize_t np = fixed_patch ? 1 : n;
  py::array_t<double> Fx(n), Fy(n), Mz(n), stick(n), pa(np), pb(np), p0(np);
  py::array_t<bool> valid(n);
  py::array_t<int> iterations(n);
  double *fx = Fx.mutable_data(), *fy = Fy.mutable_data(), *mz = Mz.mutable_data(), *st = stick.mutable_data();
  double *oa = pa.mutable_data(), *ob = pb.mutable_data(), *op0 = p0.mutable_data();
  bool* ok = valid.mutable_data();
  int* it = iterations.mutable_data();
  // Validity reasons are static texts: per point the index of its text in
  // reason_texts (0: valid, ""), so that invalid points cost no allocation.
  py::array_t<std::int16_t> reason(n);
  std::int16_t* rs = reason.mutable_data();
  std::vector<const char*> texts = {""};
  {
    py::gil_scoped_release release;
    contact::ContactInput in;
    // The Hertz patch: once when its data are one value each, else per point
    // when they change from the previous point.
    const auto solve_patch = [&](py::ssize_t i) {
      in.material.E = cE[i];
      in.material.nu = cnu[i];
      in.patch = curvatures ? contact::hertz_from_load(c1[i], c2[i], cf[i], in.material)
                            : contact::hertz_from_semi_axes(c1[i], c2[i], cf[i], in.material);
      if (curvatures && !(in.patch.a >= 1e-6 && in.patch.a <= 1.0 && in.patch.b >= 1e-6 && in.patch.b <= 1.0)) {
        std::ostringstream m;
        m << "point " << i << ": the patch of A, B and Fz has semi-axes a = " << in.patch.a << " m, b = " << in.patch.b
          << " m: expected values in [1e-06, 1] m";
        throw InputError(m.str());
      }
    };
    if (fixed_patch) {
      solve_patch(0);
      oa[0] = in.patch.a, ob[0] = in.patch.b, op0[0] = in.patch.p0;
    }
    for (py::ssize_t i = 0; i < n; ++i) {
      if (!fixed_patch && (i == 0 || c1[i] != c1[i - 1] || c2[i] != c2[i - 1] || cf[i] != cf[i - 1] ||
                           cE[i] != cE[i - 1] || cnu[i] != cnu[i - 1]))
        solve_patch(i);
      in.material.mu = cmu[i];
      in.creep = {cx[i], ce[i], cp[i]};
      in.reduction = {ck1[i], ck2[i], ck3[i]};
      in.rolling_speed = cv[i];
      const contact::ContactForces f = model->solve(in, ws.get());
      fx[i] = f.Fx;
      fy[i] = f.Fy;
      mz[i] = f.Mz;
      ok[i] = f.valid;
      it[i] = f.iterations;
      st[i] = f.stick_fraction;
      if (!fixed_patch) oa[i] = in.patch.a, ob[i] = in.patch.b, op0[i] = in.patch.p0;
      std::int16_t code = 0;
      if (!f.valid) {
        const char* why = f.reason ? f.reason : "";
        while (code < static_cast<std::int16_t>(texts.size()) && texts[static_cast<std::size_t>(code)] != why) ++code;
        if (code == static_cast<std::int16_t>(texts.size()) && texts.size() < 30000) texts.push_back(why);
      }
      rs[i] = code;
    }
  }
  py::dict r;
  r["Fx"] = Fx;
  r["Fy"] = Fy;
  r["Mz"] = Mz;
  r["valid"] = valid;
  r["iterations"] = iterations;
  r["stick_fraction"] = stick;
  if (fixed_patch) {
    r["a"] = pa.at(0), r["b"] = pb.at(0), r["p0"] = p0.at(0);
  } else {
    r["a"] = pa, r["b"] = pb, r["p0"] = p0;
  }
  r["reason"] = reason;
  py::list why;
  for (const char* t : texts) why.append(py::str(t));
  r["reason_texts"] = why;
  r["model"] = std::string(model->name());
  return r;
}

py::list model_list() {
  py::list l;
  for (const auto& e : contact::tangential_models()) {
    py::dict d;
    d["name"] = e.name;
    d["description"] = e.description;
    d["tabulated"] = e.tabulated;
    d["compared_by_default"] = e.compared_by_default();
    l.append(d);
  }
  return l;
}

// The exact solver on one Hertzian patch: fields on the grid (rows along y).
py::dict mim_fields(double s1, double s2, bool curvatures, double Fz, double xi, double eta, double phi, double E,
                    double nu, double mu, int grid, double tolerance) {
  contact::mim::MimOptions o;
  if (grid > 0) o.grid = grid;
  if (tolerance > 0) o.tolerance = tolerance;
  o.check();
  constexpr double kHuge = std::numeric_limits<double>::max();
  for (const auto& [v, name] : {std::pair{xi, "xi"}, std::pair{eta, "eta"}, std::pair{phi, "phi"}})
    check_range(one(v), name, -kHuge, kHuge);
  check_range(one(mu), "mu", 0.0, 2.0, true);
  const contact::Material m{E, nu, mu};
  const contact::HertzPatch patch = checked_hertz_patch(s1, s2, curvatures, Fz, m);
  contact::mim::MimSolver solver(o);
  const contact::mim::MimSolution* s = nullptr;
  {
    py::gil_scoped_release release;
    s = &solver.solve_hertz(patch, {xi, eta, phi}, m);
  }
  const auto& g = s->grid;
  const std::vector<py::ssize_t> shape = {g.my, g.mx};
  auto field = [&](const std::vector<double>& v) {
    py::array_t<double> a(shape);
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  py::array_t<std::uint8_t> state(shape);
  for (std::size_t i = 0; i < s->state.size(); ++i) state.mutable_data()[i] = static_cast<std::uint8_t>(s->state[i]);
  py::array_t<double> x(g.mx), y(g.my);
  for (int i = 0; i < g.mx; ++i) x.mutable_data()[i] = g.x(i);
  for (int j = 0; j < g.my; ++j) y.mutable_data()[j] = g.y(j);
  py::dict r;
  r["x"] = x;
  r["y"] = y;
  r["pressure"] = field(s->pn);
  r["px"] = field(s->px);
  r["py"] = field(s->py);
  r["state"] = state;
  r["Fx"] = s->Fx;
  r["Fy"] = s->Fy;
  r["Mz"] = s->Mz;
  r["Fz"] = s->Fz;
  r["approach"] = s->approach;
  r["n_contact"] = s->n_contact;
  r["n_adhesion"] = s->n_adhesion;
  r["n_slip"] = s->n_slip;
  r["converged"] = s->converged();
  r["a"] = patch.a;
  r["b"] = patch.b;
  r["p0"] = patch.p0;
  return r;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def("tangential_models", &model_list, "Registered tangential (creep-force) models: name, description, tabulated, compared_by_default");
  m.def("_contact_solve", &solve_arrays, py::arg("model"), py::arg("curvatures"), py::arg("xi"), py::arg("eta"),
        py::arg("phi"), py::arg("s1"), py::arg("s2"), py::arg("Fz"), py::arg("E"), py::arg("nu"), py::arg("mu"),
        py::arg("V"), py::arg("k11"), py::arg("k22"), py::arg("k23"), py::arg("grid") = 0,
        py::arg("tolerance") = 0.0, py::arg("cache_dir") = "", py::arg("extrapolation") = "default");
  m.def("_mim_fields", &mim_fields, py::arg("s1"), py::arg("s2"), py::arg("curvatures"), py::arg("Fz"),
        py::arg("xi"), py::arg("eta"), py::arg("phi"), py::arg("E"), py::arg("nu"), py::arg("mu"),
        py::arg("grid") = 0, py::arg("tolerance") = 0.0);
  m.def("_parse_reduction", [](const std::string& text) {
    const contact::ReductionFactors k = contact::parse_reduction(text, "reduction");
    return py::make_tuple(k.k11, k.k22, k.k23);
  }, py::arg("text"));
  m.def("hertz_patch", [](double s1, double s2, bool curvatures, double Fz, double E, double nu) {
    const contact::HertzPatch p = checked_hertz_patch(s1, s2, curvatures, Fz, contact::Material{E, nu, 0.3});
    py::dict d;
    d["A"] = p.A, d["B"] = p.B, d["a"] = p.a, d["b"] = p.b, d["p0"] = p.p0, d["approach"] = p.approach, d["Fz"] = p.Fz;
    return d;
  }, py::arg("s1"), py::arg("s2"), py::arg("curvatures"), py::arg("Fz"), py::arg("E"), py::arg("nu"));
}

}  // namespace railsim::python
