// Python bindings of profiles, the wheel-rail contact geometry and conicity:
// read_profile (a file or a shipped name: S1002, UIC60, UIC60_MBench,
// UIC60_true) with its points as arrays [m]; the contact table versus lateral
// shift y [m] (columns as `railsim geometry`, ContactTable::column_names(),
// angles in rad; cached as the program caches it); equivalent conicity
// (EN 15302 regression, contact/geometry/conicity.hpp) and the
// rolling-radius difference, as `railsim conicity`.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "contact/geometry/conicity.hpp"
#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/profile.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "core/errors.hpp"
#include "python/src/bindings.hpp"

namespace py = pybind11;

namespace railsim::python {

namespace {

contact::ProfileKind kind_of(const std::string& k) {
  if (k == "wheel") return contact::ProfileKind::wheel;
  if (k == "rail") return contact::ProfileKind::rail;
  throw InputError("kind: expected 'wheel' or 'rail' (got '" + k + "')");
}

py::array_t<double> to_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// Profiles, track set-up and the geometry built from them (kept together: the
// geometry refers to its profiles).
struct Geometry {
  std::unique_ptr<contact::Profile> wheel, rail;
  std::unique_ptr<contact::WheelRailGeometry> geometry;
};

std::shared_ptr<Geometry> make_geometry(const std::string& wheel, const std::string& rail,
                                        const std::string& inclination, double gauge, double gauge_depth,
                                        double flange_back, double back_face, double r0) {
  auto g = std::make_shared<Geometry>();
  g->wheel = std::make_unique<contact::Profile>(contact::read_profile(wheel, contact::ProfileKind::wheel));
  g->rail = std::make_unique<contact::Profile>(contact::read_profile(rail, contact::ProfileKind::rail));
  contact::TrackSetup ts;
  ts.gauge = gauge;
  ts.gauge_depth = gauge_depth;
  ts.flange_back = flange_back;
  ts.back_face = back_face;
  ts.r0 = r0;
  ts.inclination = contact::parse_inclination(inclination, "inclination");
  g->geometry = std::make_unique<contact::WheelRailGeometry>(*g->wheel, *g->rail, ts);
  return g;
}

contact::ContactTable table_of(const Geometry& g, double y_min, double y_max, double y_step, bool cache,
                               const std::string& cache_dir) {
  contact::TableGrid grid{y_min, y_max, y_step};
  grid.validate();
  py::gil_scoped_release release;
  return cache ? contact::ContactTable::cached(*g.geometry, *g.wheel, *g.rail, grid, cache_dir)
               : contact::ContactTable::build(*g.geometry, grid);
}

py::dict table_dict(const contact::ContactTable& t) {
  py::dict d;
  const auto names = contact::ContactTable::column_names();
  for (int c = 0; c < contact::ContactTable::kColumns; ++c) {
    py::array_t<double> a(static_cast<py::ssize_t>(t.rows()));
    for (std::size_t r = 0; r < t.rows(); ++r) a.mutable_data()[r] = t.value(r, c);
    d[py::str(names[static_cast<std::size_t>(c)])] = a;
  }
  return d;
}

py::dict point_dict(const contact::ContactPoint& p) {
  py::dict d;
  d["y"] = p.y, d["z"] = p.z, d["y_wheel"] = p.y_wheel, d["y_rail"] = p.y_rail, d["radius"] = p.radius;
  d["angle"] = p.angle, d["A"] = p.A, d["B"] = p.B, d["gap"] = p.gap;
  return d;
}

}  // namespace

void bind_geometry(py::module_& m) {
  py::class_<contact::Profile>(m, "Profile", "A wheel or rail profile: points y, z [m] (field side +y, z down)")
      .def_property_readonly("kind", [](const contact::Profile& p) {
        return p.kind() == contact::ProfileKind::wheel ? "wheel" : "rail";
      })
      .def_property_readonly("source", &contact::Profile::source)
      .def_property_readonly("y", [](const contact::Profile& p) { return to_array(p.y()); })
      .def_property_readonly("z", [](const contact::Profile& p) { return to_array(p.z()); })
      .def("__repr__", [](const contact::Profile& p) {
        return "<railsim.Profile " + p.source() + ", " + std::to_string(p.y().size()) + " points>";
      });
  m.def("read_profile",
        [](const std::string& path_or_name, const std::string& kind, double unit, bool mirror_y, bool z_up) {
          contact::ProfileReadOptions o;
          o.unit = unit;
          o.mirror_y = mirror_y;
          o.z_up = z_up;
          return contact::read_profile(path_or_name, kind_of(kind), o);
        },
        py::arg("path_or_name"), py::arg("kind"), py::arg("unit") = 0.0, py::arg("mirror_y") = false,
        py::arg("z_up") = false, "Read a profile file or a shipped profile by name");
  m.def("shipped_profile_names", &contact::shipped_profile_names);

  py::class_<Geometry, std::shared_ptr<Geometry>>(m, "WheelRailGeometry",
                                                  "Contact search between a wheelset's wheel and rail profiles")
      .def(py::init(&make_geometry), py::arg("wheel") = "S1002", py::arg("rail") = "UIC60",
           py::arg("inclination") = "1/40", py::arg("gauge") = 1.435, py::arg("gauge_depth") = 0.014,
           py::arg("flange_back") = 1.360, py::arg("back_face") = -0.070, py::arg("r0") = 0.46)
      .def_property_readonly("wheel", [](const Geometry& g) { return *g.wheel; })
      .def_property_readonly("rail", [](const Geometry& g) { return *g.rail; })
      .def("solve",
           [](const Geometry& g, double y, double yaw) {
             const contact::WheelsetContact c = g.geometry->solve(y, yaw);
             py::dict d;
             d["y"] = c.y, d["yaw"] = c.yaw, d["roll"] = c.roll, d["z"] = py::make_tuple(c.z[0], c.z[1]);
             const char* sides[2] = {"left", "right"};
             for (int s = 0; s < 2; ++s) {
               py::list pts;
               const auto& w = c.wheel[static_cast<std::size_t>(s)];
               for (int k = 0; k < w.n; ++k) pts.append(point_dict(w.p[static_cast<std::size_t>(k)]));
               d[sides[s]] = pts;
             }
             return d;
           },
           py::arg("y"), py::arg("yaw") = 0.0, "Contact points at lateral shift y [m] and yaw [rad]")
      .def("table",
           [](const Geometry& g, double y_min, double y_max, double y_step, bool cache, const std::string& cache_dir) {
             return table_dict(table_of(g, y_min, y_max, y_step, cache, cache_dir));
           },
           py::arg("y_min") = -0.012, py::arg("y_max") = 0.012, py::arg("y_step") = 1e-4, py::arg("cache") = true,
           py::arg("cache_dir") = "", "Contact table versus lateral shift (the columns of `railsim geometry`)")
      .def("conicity",
           [](const Geometry& g, const std::vector<double>& amplitudes, double y_min, double y_max, double y_step,
              bool cache, const std::string& cache_dir) {
             const contact::ContactTable t = table_of(g, y_min, y_max, y_step, cache, cache_dir);
             std::vector<double> c;
             for (std::size_t i = 0; i < amplitudes.size(); ++i) {
               try {
                 c.push_back(contact::equivalent_conicity(t, amplitudes[i]));
               } catch (const InputError& e) {
                 throw InputError("amplitudes[" + std::to_string(i) + "]: " + e.what());
               }
             }
             const auto rr = contact::rolling_radius_difference(t);
             py::dict d;
             d["amplitude"] = to_array(amplitudes);
             d["equivalent_conicity"] = to_array(c);
             d["y"] = to_array(rr.y);
             d["delta_r"] = to_array(rr.delta_r);
             return d;
           },
           py::arg("amplitudes") = std::vector<double>{1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3}, py::arg("y_min") = -0.012,
           py::arg("y_max") = 0.012, py::arg("y_step") = 1e-4, py::arg("cache") = true, py::arg("cache_dir") = "",
           "Equivalent conicity at the amplitudes [m] and the rolling-radius difference, as `railsim conicity`");
}

}  // namespace railsim::python
