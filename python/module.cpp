// talus._talus: the run layer's RunSession and validate() for Python. The
// package (talus/__init__.py) builds the user's API on these: Run, read_run,
// callbacks. State arrays are numpy views of the method's own memory.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/core/version.hpp"
#include "talus/io/toml_reader.hpp"
#include "talus/run/run.hpp"
#include "talus/run/session.hpp"

namespace py = pybind11;
using talus::run::RunRequest;
using talus::run::RunSession;
using talus::run::StateArray;

namespace {

std::unique_ptr<RunSession> open_session(const std::string& file, const std::string& text,
                                         const std::string& out, const std::string& resume,
                                         const std::vector<std::string>& sets, int threads,
                                         bool force, bool allow_long_run) {
  RunRequest req;
  req.file = file, req.text = text, req.out = out, req.resume = resume, req.sets = sets;
  req.threads = threads, req.force = force, req.allow_long_run = allow_long_run;
  return std::make_unique<RunSession>(req);
}

// A numpy view of one state array; `owner` (the Python session) stays alive
// while the view does.
py::array view(const StateArray& a, py::handle owner) {
  const bool f64 = a.type == StateArray::Type::Float64;
  const py::dtype dtype = f64 ? py::dtype::of<double>() : py::dtype::of<std::int64_t>();
  const auto item = static_cast<py::ssize_t>(f64 ? sizeof(double) : sizeof(std::int64_t));
  std::vector<py::ssize_t> shape, strides(a.shape.size());
  for (std::size_t n : a.shape) shape.push_back(static_cast<py::ssize_t>(n));
  py::ssize_t stride = item;
  for (std::size_t k = shape.size(); k-- > 0;) strides[k] = stride, stride *= shape[k];
  if (!a.strides.empty())
    for (std::size_t k = 0; k < strides.size(); ++k) strides[k] = a.strides[k];
  py::array out(dtype, shape, strides, a.data, owner);
  if (!a.writable) out.attr("flags").attr("writeable") = false;
  return out;
}

// Up to `steps` steps (< 0: no limit) towards `until`, in pieces of about a
// tenth of a second of wall time: between pieces Python's signals are looked
// at (Ctrl-C raises KeyboardInterrupt; the run can still be finished), and
// while a piece runs the GIL is free for other Python threads. The pieces do
// not change the results (outputs fall on the same times however the loop
// is driven).
std::int64_t advance(RunSession& s, double until, std::int64_t steps) {
  using Clock = std::chrono::steady_clock;
  // Held across the pieces: between them this thread waits for the GIL, and
  // another Python thread must not step or change the run meanwhile.
  const RunSession::Claim claim(s);
  std::int64_t taken = 0, piece = 1;
  for (;;) {
    const std::int64_t ask = steps < 0 ? piece : std::min(piece, steps - taken);
    if (ask <= 0) break;
    const auto t0 = Clock::now();
    std::int64_t got = 0;
    {
      py::gil_scoped_release free_python;
      got = s.advance(until, ask).steps;
    }
    taken += got;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (got < ask) break;  // at `until`, the end, or the method stopped
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (seconds < 0.05 && piece < (std::int64_t{1} << 40)) piece *= 2;
    if (seconds > 0.2 && piece > 1) piece /= 2;
  }
  return taken;
}

// A velocity from Python: 2 or 3 numbers (z = 0 when 2).
talus::Vec3 vector3(const std::vector<double>& v, const char* what) {
  if (v.size() != 2 && v.size() != 3)
    throw talus::InputError(std::string(what) + ": expected 2 or 3 numbers, got " +
                            std::to_string(v.size()));
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0};
}

py::tuple tuple3(const talus::Vec3& v) { return py::make_tuple(v.x(), v.y(), v.z()); }

py::dict reading(const talus::run::WallReading& w) {
  py::dict d;
  d["name"] = w.name;
  d["force"] = tuple3(w.force);
  d["torque"] = tuple3(w.torque);
  d["displacement"] = tuple3(w.displacement);
  d["velocity"] = tuple3(w.velocity);
  d["pressure"] = w.pressure;
  d["servo_pressure"] = w.servo_pressure;
  d["servo_speed"] = w.servo_speed;
  d["servo_area"] = w.servo_area;
  return d;
}

}  // namespace

PYBIND11_MODULE(_talus, m) {
  m.doc() = "talus's run layer (use the talus package, not this module)";
  py::register_exception<talus::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<talus::RunError>(m, "RunError", PyExc_RuntimeError);
  m.attr("__version__") = talus::version();
  m.attr("DICT_SCENARIO") = std::string(talus::io::kDictScenario);
  m.def(
      "validate",
      [](const std::string& path, const std::vector<std::string>& sets, bool allow_long_run) {
        return talus::run::validate(path, sets, allow_long_run);
      },
      py::arg("path"), py::arg("sets"), py::arg("allow_long_run") = false);
  m.def(
      "validate_text",
      [](const std::string& text, const std::string& path, const std::vector<std::string>& sets,
         bool allow_long_run) {
        return talus::run::validate_text(text, path, sets, allow_long_run);
      },
      py::arg("text"), py::arg("path"), py::arg("sets"), py::arg("allow_long_run") = false);
  py::class_<RunSession>(m, "Session")
      .def(py::init(&open_session), py::arg("file"), py::arg("text"), py::arg("out"),
           py::arg("resume"), py::arg("sets"), py::arg("threads"), py::arg("force"),
           py::arg("allow_long_run"))
      .def("advance", &advance, py::arg("until"), py::arg("steps"))
      .def("finish",
           [](RunSession& s) {
             const auto r = s.finish();
             py::dict out;
             out["out"] = r.out.string();
             out["headline"] = r.headline;
             out["warnings"] = r.warnings;
             return out;
           })
      .def_property_readonly("time", [](const RunSession& s) { return s.simulation().time(); })
      .def_property_readonly("steps", [](const RunSession& s) { return s.simulation().steps(); })
      .def_property_readonly("end_time",
                             [](const RunSession& s) { return s.simulation().end_time(); })
      .def_property_readonly("time_step",
                             [](const RunSession& s) { return s.simulation().time_step(); })
      .def_property_readonly("done", &RunSession::done)
      .def_property_readonly("reorders",
                             [](const RunSession& s) { return s.simulation().reorders(); })
      .def("checkpoint", &RunSession::checkpoint)
      .def("resolved_json", [](RunSession& s) { return s.resolved().dump(); })
      .def("walls",
           [](const RunSession& s) {
             py::list out;
             for (const auto& w : s.walls()) out.append(reading(w));
             return out;
           })
      .def(
          "set_wall_velocity",
          [](RunSession& s, const std::string& name, const std::vector<double>& v) {
            s.set_wall_velocity(name, vector3(v, ("wall '" + name + "': velocity").c_str()));
          },
          py::arg("name"), py::arg("velocity"))
      .def("set_wall_servo", &RunSession::set_wall_servo, py::arg("name"), py::arg("pressure"),
           py::arg("speed"), py::arg("area"))
      .def_property_readonly("finished", &RunSession::finished)
      .def_property_readonly("stepping", &RunSession::stepping)
      .def_property_readonly("out", [](const RunSession& s) { return s.out().string(); })
      .def("arrays",
           [](py::object self) {
             auto& s = self.cast<RunSession&>();
             py::dict out;
             for (const auto& a : s.simulation().state_arrays())
               out[a.name.c_str()] = view(a, self);
             return out;
           })
      .def("units", [](RunSession& s) {
        py::dict out;
        for (const auto& a : s.simulation().state_arrays()) out[a.name.c_str()] = a.unit;
        return out;
      });
}
