// SPDX-License-Identifier: BSD-3-Clause
// Files (io/records.hpp, io/case_file.hpp, io/outputs.hpp): records, case files and the outputs
// the command line writes, byte for byte the same.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/io/azimuth_outputs.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/sim/rocking_frame.hpp"
#include "flexrock/study/azimuths.hpp"

namespace py = pybind11;

namespace flexrock::python {

void bind_io(py::module_& m) {
  py::enum_<io::AccelUnit>(m, "AccelUnit")
      .value("g", io::AccelUnit::kG)
      .value("m_per_s2", io::AccelUnit::kMetersPerSecond2)
      .value("cm_per_s2", io::AccelUnit::kCentimetersPerSecond2);

  py::class_<io::Record>(m, "Record", "An acceleration record, values in the file's units.")
      .def_readonly("source", &io::Record::source)
      .def_readonly("header", &io::Record::header)
      .def_readonly("units", &io::Record::units)
      .def_readonly("dt", &io::Record::dt, "[s] 0 if not uniform")
      .def_property_readonly(
          "time",
          [](const io::Record& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.time.size()), r.time.data());
          },
          "[s] numpy array (a copy)")
      .def_property_readonly(
          "values",
          [](const io::Record& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.values.size()), r.values.data());
          },
          "in `units`, numpy array (a copy)")
      .def_property_readonly("npts", &io::Record::npts)
      .def_property_readonly("duration", &io::Record::duration)
      .def("to_si", &io::Record::to_si, py::arg("scale") = 1.0)
      .def("to_motion", &io::Record::to_motion, py::arg("scale") = 1.0,
           "The record as a horizontal ground motion [m/s^2] times `scale`.")
      .def("__repr__", [](const io::Record& r) {
        static const char* names[] = {"g", "m/s^2", "cm/s^2"};
        double peak = 0.0;
        for (double v : r.values) peak = std::max(peak, std::abs(v));
        std::ostringstream o;
        o.precision(4);
        o << "<Record " << r.source << ": " << r.npts() << " samples";
        if (r.dt > 0.0) o << " every " << r.dt << " s";
        o << ", " << r.duration() << " s, peak " << peak << " " << names[static_cast<int>(r.units)]
          << ">";
        return o.str();
      });
  m.def("read_at2", &io::read_at2, py::arg("path"), R"doc(Reads a PEER NGA .AT2 record.

Parameters
----------
path : str

Returns
-------
Record
    Values in g, as the file states, with its dt [s].)doc");
  m.def("read_single_column", &io::read_single_column, py::arg("path"), py::arg("dt"),
        py::arg("units"), R"doc(Reads a record of one value a line, sampled every dt.

Parameters
----------
path : str
dt : float
    [s] sample spacing.
units : AccelUnit
    Units of the file's values.

Returns
-------
Record)doc");
  m.def("read_time_series", &io::read_time_series, py::arg("path"), py::arg("units") = py::none(),
        R"doc(Reads time/acceleration pairs, one a line (blanks, commas or semicolons).

Parameters
----------
path : str
units : AccelUnit, optional
    Units of the accelerations (times in s); required unless a row of the file states them
    ("s, g" or "time [s], acc [cm/s^2]"), and if both, they must agree.

Returns
-------
Record)doc");
  m.def("read_smc", &io::read_smc, py::arg("path"), R"doc(Reads a USGS SMC accelerogram.

Parameters
----------
path : str

Returns
-------
Record
    Values in cm/s^2, dt from the file's sampling rate.)doc");
  m.def("read_knet", &io::read_knet, py::arg("path"),
        R"doc(Reads a NIED K-NET or KiK-net ASCII file.

Parameters
----------
path : str

Returns
-------
Record
    Counts times the file's scale factor, in cm/s^2 (offset kept as published).)doc");
  m.def("read_esm", &io::read_esm, py::arg("path"), R"doc(Reads an ESM ASCII acceleration file.

Parameters
----------
path : str

Returns
-------
Record
    Values in the units the file states (UNITS), dt from SAMPLING_INTERVAL_S.)doc");
  m.def("read_cosmos", &io::read_cosmos, py::arg("path"),
        R"doc(Reads the first acceleration block of a COSMOS V1 or V2 file.

Parameters
----------
path : str

Returns
-------
Record
    Values in the units its data line states, dt from real header value 62.)doc");

  py::class_<io::RecordFormat>(m, "RecordFormat", "A record format of the table of formats.")
      .def_property_readonly("name", [](const io::RecordFormat& f) { return std::string(f.name); })
      .def_property_readonly("suffixes",
                             [](const io::RecordFormat& f) {
                               std::vector<std::string> v;
                               std::istringstream in(f.suffixes);
                               for (std::string x; in >> x;) v.push_back(x);
                               return v;
                             })
      .def_property_readonly("needs_dt", [](const io::RecordFormat& f) { return f.needs_dt; })
      .def_property_readonly(
          "needs_units",
          [](const io::RecordFormat& f) { return f.units == io::RecordUnits::kGiven; },
          "the file never states its units: they must be given")
      .def_property_readonly("publisher",
                             [](const io::RecordFormat& f) { return std::string(f.publisher); })
      .def_property_readonly("doc", [](const io::RecordFormat& f) { return std::string(f.doc); })
      .def("__repr__",
           [](const io::RecordFormat& f) { return "<RecordFormat " + std::string(f.name) + ">"; });
  m.def(
      "record_formats",
      [] {
        std::vector<const io::RecordFormat*> v;
        for (const io::RecordFormat& f : io::record_formats()) v.push_back(&f);
        return v;
      },
      py::return_value_policy::reference,
      R"doc(Every record format: the one table case files, study files and read_record use.

Returns
-------
list of RecordFormat)doc");
  // a loaded case's run: a rocking frame's through simulate_frame (its model's stops), any other
  // body's through simulate
  m.def(
      "_simulate_case",
      [](const io::Case& c) {
        return c.frame ? simulate_frame(*c.frame, c.motion, c.initial, c.options)
                       : simulate(Body(c.body), c.motion, c.initial, c.options);
      },
      py::arg("case"), py::call_guard<py::gil_scoped_release>());
  m.def("_read_record", &io::read_record, py::arg("path"), py::arg("format"), py::arg("dt"),
        py::arg("units"));
  m.def(
      "combine",
      [](const io::Record& h, const io::Record* v, double scale) {
        return io::combine(h, v, scale);
      },
      py::arg("horizontal"), py::arg("vertical") = nullptr, py::arg("scale") = 1.0,
      R"doc(A horizontal record and an optional vertical one as one ground motion.

Parameters
----------
horizontal : Record
vertical : Record, optional
    Resampled onto the horizontal's times.
scale : float
    [-] factor on both.

Returns
-------
GroundMotion
    Accelerations in m/s^2.)doc");

  py::class_<io::ExcitationComponent>(m, "ExcitationComponent",
                                      "One component of the excitation, as a case describes it.")
      .def(py::init<>())
      .def_readwrite("type", &io::ExcitationComponent::type)
      .def_readwrite("file", &io::ExcitationComponent::file)
      .def_readwrite("format", &io::ExcitationComponent::format)
      .def_readwrite("units", &io::ExcitationComponent::units)
      .def_readwrite("amplitude", &io::ExcitationComponent::amplitude, "[m/s^2]")
      .def_readwrite("scale", &io::ExcitationComponent::scale);

  py::class_<io::OutputSettings>(m, "OutputSettings")
      .def(py::init<>())
      .def_readwrite("dt", &io::OutputSettings::dt, "[s]")
      .def_readwrite("time_history", &io::OutputSettings::time_history)
      .def_readwrite("summary", &io::OutputSettings::summary)
      .def_readwrite("events", &io::OutputSettings::events);

  py::class_<io::Case>(m, "Case", "A case: everything a run needs (see load_case).")
      .def(py::init<>())
      .def_readwrite("source", &io::Case::source)
      .def_readwrite("stem", &io::Case::stem)
      .def_readwrite("name", &io::Case::name)
      .def_readwrite("description", &io::Case::description)
      .def_readwrite("body_type", &io::Case::body_type)
      .def_readwrite("rigid", &io::Case::rigid)
      .def_readwrite("body", &io::Case::body)
      .def_readonly("support", &io::Case::support,
                    "SupportParameters of [support], or None: the rigid floor")
      .def_readwrite("motion", &io::Case::motion)
      .def_readwrite("horizontal", &io::Case::horizontal)
      .def_readwrite("vertical", &io::Case::vertical)
      .def_readwrite("horizontal2", &io::Case::horizontal2)
      .def_readonly("body3d", &io::Case::body3d,
                    "AxisymmetricBody of a cylinder or body_of_revolution (None: another type); "
                    "with a record pair the case runs in 3D")
      .def_property_readonly("has_pair", [](const io::Case& c) { return c.pair != nullptr; })
      .def_readwrite("azimuth_deg", &io::Case::azimuth)
      .def_readwrite("azimuth_step_deg", &io::Case::azimuth_step)
      .def_readwrite("excitation_scale", &io::Case::excitation_scale)
      .def_readwrite("initial", &io::Case::initial)
      .def_readwrite("options", &io::Case::options)
      .def_readwrite("output", &io::Case::output)
      .def_readwrite("restraints", &io::Case::restraints);
  m.def("load_case", &io::load_case, py::arg("path"),
        R"doc(Reads and checks a case file (TOML, docs/case-file.md).

Parameters
----------
path : str

Returns
-------
Case
    Body, motion (m/s^2), initial state, solver options and outputs; bad input raises
    InputError naming file, line and key.)doc");
  m.def(
      "azimuth_motion",
      [](const io::Case& c, double beta) {
        if (!c.pair) throw flexrock::InputError(c.source + ": the case has no record pair");
        return io::azimuth_motion(c, beta);
      },
      py::arg("case"), py::arg("azimuth_deg"),
      R"doc(The ground motion of a case with a record pair at one azimuth: H1 cos(beta) + H2
sin(beta), beta [deg] from H1 toward H2, scaled and with the vertical as the case says.)doc");
  m.def(
      "run_azimuths",
      [](const io::Case& c, std::optional<double> step_deg, int threads) {
        if (!c.pair) throw flexrock::InputError(c.source + ": the case has no record pair");
        const Body body(c.body);
        const std::vector<double> grid = study::azimuth_grid(step_deg.value_or(c.azimuth_step));
        std::vector<study::AzimuthRun> rows;
        {
          py::gil_scoped_release nogil;
          study::RunOptions run;
          run.threads = threads;
          rows = study::run_azimuths(
              body, grid, [&](double b) { return io::azimuth_motion(c, b); }, c.initial, c.options,
              run);
        }
        const study::AzimuthEnvelope e = study::envelope(rows);
        // typed columns: numbers as numpy arrays, the outcome as a list of str
        py::dict table;
        auto col = [&](const char* name, auto get) {
          py::array_t<double> a(static_cast<py::ssize_t>(rows.size()));
          auto v = a.mutable_unchecked<1>();
          for (std::size_t i = 0; i < rows.size(); ++i)
            v(static_cast<py::ssize_t>(i)) = get(rows[i]);
          table[name] = a;
        };
        using R = study::AzimuthRun;
        col("azimuth_deg", [](const R& r) { return r.azimuth_deg; });
        py::list outcome;
        for (const R& r : rows) outcome.append(study::to_string(r.summary.outcome));
        table["outcome"] = outcome;
        col("max_theta_rad", [](const R& r) { return r.summary.max_theta; });
        col("max_theta_edge1_rad", [](const R& r) { return r.max_theta_edge1; });
        col("max_theta_edge2_rad", [](const R& r) { return r.max_theta_edge2; });
        col("max_theta_over_alpha", [](const R& r) { return r.summary.max_theta_over_alpha; });
        col("overturn_time_s", [](const R& r) { return r.summary.overturn_time; });
        col("impacts", [](const R& r) { return static_cast<double>(r.summary.impacts); });
        col("max_impact_force_N", [](const R& r) { return r.max_impact_force; });
        col("max_offset_m", [](const R& r) { return r.summary.max_offset; });
        col("final_offset_m", [](const R& r) { return r.summary.final_offset; });
        col("pga_along_m_per_s2", [](const R& r) { return r.pga_along; });
        col("pga_across_m_per_s2", [](const R& r) { return r.pga_across; });
        py::dict env;
        env["max_theta_rad"] = e.max_theta;
        env["max_theta_azimuth_deg"] = e.max_theta_azimuth;
        env["max_theta_over_alpha"] = e.max_theta_over_alpha;
        env["pga_along_at_max_theta_m_per_s2"] = e.pga_along_at_max_theta;
        env["pga_across_at_max_theta_m_per_s2"] = e.pga_across_at_max_theta;
        env["max_offset_m"] = e.max_offset;
        env["max_offset_azimuth_deg"] = e.max_offset_azimuth;
        env["max_impact_force_N"] = e.max_impact_force;
        env["max_impact_force_azimuth_deg"] = e.max_impact_force_azimuth;
        env["overturned_azimuths_deg"] = e.overturned_azimuths;
        env["first_overturn_time_s"] = e.first_overturn_time;
        env["first_overturn_azimuth_deg"] = e.first_overturn_time >= 0.0
                                                ? py::object(py::float_(e.first_overturn_azimuth))
                                                : py::object(py::none());
        env["stopped_azimuths_deg"] = e.stopped_azimuths;
        return py::make_tuple(table, env);
      },
      py::arg("case"), py::arg("step_deg") = py::none(), py::arg("threads") = 0,
      R"doc(Runs a case with a record pair at every azimuth of the grid over [0, 360) (as
``flexrock azimuths``), on threads with the GIL released.

Parameters
----------
case : Case
    From ``load_case`` of a file with ``[excitation.horizontal2]``.
step_deg : float, optional
    [deg] the grid's step (default: the case's ``azimuth_step_deg``, 5).
threads : int
    Worker threads (0: every core).

Returns
-------
(dict, dict)
    The per-azimuth table (numpy arrays of float, ``outcome`` a list of str; the columns of the
    azimuth CSV) and the envelope (largest tilt, offset and impact force with their governing
    azimuths, the overturned azimuths).)doc");
  m.def(
      "load_body",
      [](const std::string& path) {
        std::string type;
        BodyParameters p = io::load_body(path, &type);
        return py::make_tuple(std::move(p), type);
      },
      py::arg("path"), R"doc(The [body] table of a case or body file.

Parameters
----------
path : str

Returns
-------
(BodyParameters, str)
    The parameters (SI) and the body's type name.)doc");

  py::class_<io::OutputPaths>(m, "OutputPaths")
      .def(py::init<>())
      .def_readwrite("time_history", &io::OutputPaths::time_history)
      .def_readwrite("summary", &io::OutputPaths::summary)
      .def_readwrite("events", &io::OutputPaths::events);

  m.def("time_history_columns", &io::time_history_columns, py::arg("modes"),
        R"doc(Column names of the time history, each with its unit suffix.

Parameters
----------
modes : int
    Deformation modes of the body.

Returns
-------
list of str
    time_s, phase, theta_rad, theta_dot_rad_per_s, uplift_m, q1..., q1_dot_per_s...,
    base_acc_x_m_per_s2, ..., impact_loss_J.)doc");
  m.def("event_columns", &io::event_columns, R"doc(Column names of the event log.

Returns
-------
list of str
    time_s, event, edge, theta_rad, theta_dot_before_rad_per_s, theta_dot_after_rad_per_s,
    energy_loss_J, impulse_x_N_s, impulse_y_N_s, friction_demand.)doc");
  m.def(
      "event_values",
      [](const SimulationResult& r) {
        // numbers as float arrays, names as lists of str (also when there is no event)
        py::list cols;
        for (io::EventColumnValues& c : io::event_values(r)) {
          if (auto* v = std::get_if<std::vector<double>>(&c)) {
            cols.append(py::array_t<double>(static_cast<py::ssize_t>(v->size()), v->data()));
          } else {
            cols.append(py::cast(std::get<std::vector<std::string>>(c)));
          }
        }
        return cols;
      },
      py::arg("result"),
      R"doc(The event log as columns, in the order of event_columns().

Parameters
----------
result : SimulationResult

Returns
-------
list
    One column per entry, one element per event: a float array, or a list of str for the
    ``event`` column (the kind's name). The values ``write_events`` prints.)doc");
  m.def(
      "time_history_csv",
      [](const SimulationResult& r, const Body& body) {
        std::ostringstream out;
        io::write_time_history(out, r, body);
        return out.str();
      },
      py::arg("result"), py::arg("body"), R"doc(The time-history CSV text ``flexrock run`` writes.

Parameters
----------
result : SimulationResult
body : Body

Returns
-------
str)doc");
  m.def(
      "time_history_arrays",
      [](const SimulationResult& r, const Body& body) {
        const std::vector<std::string> names = io::time_history_columns(r.history.modes);
        std::vector<std::vector<double>> values = io::time_history_values(r, body);
        py::dict out;
        for (std::size_t j = 0; j < names.size(); ++j) {
          // the numpy array owns the column: no copy
          auto* v = new std::vector<double>(std::move(values[j]));
          py::capsule owner(v, [](void* p) { delete static_cast<std::vector<double>*>(p); });
          out[py::str(names[j])] =
              py::array_t<double>(static_cast<py::ssize_t>(v->size()), v->data(), owner);
        }
        return out;
      },
      py::arg("result"), py::arg("body"),
      R"doc(The time history as numpy arrays, by the CSV's column names.

Parameters
----------
result : SimulationResult
    A finished simulation.
body : Body
    The body it simulated (for the uplift column).

Returns
-------
dict of str to numpy.ndarray
    One float64 array per column of :func:`time_history_columns` (``time_s`` [s], ``phase``,
    ``theta_rad`` [rad], ..., ``impact_loss_J`` [J]), equal bit for bit to the values of
    :func:`time_history_csv`.)doc");
  m.def(
      "events_csv",
      [](const SimulationResult& r) {
        std::ostringstream out;
        io::write_events(out, r);
        return out.str();
      },
      py::arg("result"), R"doc(The event-log CSV text ``flexrock run`` writes.

Parameters
----------
result : SimulationResult

Returns
-------
str)doc");
  m.def(
      "summary_json",
      [](const io::Case& c, const Body& b, const SimulationResult& r, const io::OutputPaths& p) {
        return io::summary_json(c, b, r, p);
      },
      py::arg("case"), py::arg("body"), py::arg("result"), py::arg("paths") = io::OutputPaths{},
      R"doc(The summary JSON text ``flexrock run`` writes (SI units, docs/case-file.md).

Parameters
----------
case : Case
body : Body
result : SimulationResult
paths : OutputPaths
    Where the outputs went, for the summary's ``outputs``.

Returns
-------
str)doc");
  m.def(
      "write_outputs",
      [](const io::Case& c, const Body& b, const SimulationResult& r, const std::string& dir) {
        return io::write_outputs(c, b, r, dir);
      },
      py::arg("case"), py::arg("body"), py::arg("result"), py::arg("output_dir") = std::string(),
      R"doc(Writes the outputs the case's [output] table asks for, atomically, summary last.

Parameters
----------
case : Case
body : Body
result : SimulationResult
output_dir : str
    Relative names are relative to it.

Returns
-------
OutputPaths)doc");
}

}  // namespace flexrock::python
