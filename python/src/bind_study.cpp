// SPDX-License-Identifier: BSD-3-Clause
// Studies (study/*.hpp, io/study_files.hpp): overturning spectra, sweeps and fragility fits.
// The GIL is released while a study runs its thread pool.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "field_pickle.hpp"
#include "flexrock/core/enum_names.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/fragility_session.hpp"
#include "flexrock/io/qualify.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/io/study_session.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/hand_estimates.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

// a study's thread pool on `threads` workers, run on a thread of its own while this one waits
// without the GIL and takes it every 20 ms to look for signals: Ctrl-C (or any signal whose
// Python handler raises) stops the pool between runs, as SIGINT stops the command line, and
// its exception is raised here once the pool has stopped (a session's journal keeps every
// finished run); from a thread other than the main one no signal is seen (Python's rule).
// `progress`: what flexrock._progress.reporter made of the keywords progress= and callback=
// (None: nothing), called on this thread with (runs done, runs to do) when the count moves and
// once at the end, then closed; an exception it raises stops the runs as Ctrl-C does
struct Progress {
  py::object reporter = py::none();
  std::size_t total = 0;
};

Progress progress_of(const py::object& bar, const py::object& callback, const char* what,
                     std::size_t total) {
  return {py::module_::import("flexrock._progress").attr("reporter")(bar, callback, what, total),
          total};
}

template <class Work>
auto interruptible(int threads, Work work, const Progress& progress = {}) {
  std::atomic<bool> cancel{false};
  std::atomic<std::size_t> completed{0};
  study::RunOptions o;
  o.threads = threads;
  o.cancel = &cancel;
  o.completed = &completed;
  auto done = std::async(std::launch::async, [&] { return work(o); });
  bool interrupted = false;
  std::size_t reported = 0;
  bool first = true;
  const bool reporting = !progress.reporter.is_none();
  auto report = [&] {
    const std::size_t n = std::min(completed.load(std::memory_order_relaxed), progress.total);
    if (!first && n == reported) return;
    first = false;
    reported = n;
    progress.reporter(n, progress.total);
  };
  for (;;) {
    std::future_status state;
    {
      py::gil_scoped_release nogil;
      state = done.wait_for(std::chrono::milliseconds(20));
    }
    if (state == std::future_status::ready) break;
    if (interrupted) continue;
    if (PyErr_CheckSignals() != 0) {
      interrupted = true;
      cancel.store(true);
      continue;
    }
    if (reporting) {
      try {
        report();
      } catch (py::error_already_set& e) {
        // the callback's exception, once the pool has stopped
        interrupted = true;
        cancel.store(true);
        e.restore();
      }
    }
  }
  if (interrupted) {
    // the signal's (or the callback's) exception wins over what the stopped pool returned or
    // threw; the bar is closed without hiding it
    try {
      done.get();
    } catch (...) {
    }
    if (reporting) {
      py::error_scope keep;
      try {
        progress.reporter.attr("close")();
      } catch (py::error_already_set&) {
      }
    }
    throw py::error_already_set();
  }
  if (reporting) {
    // the last count, then the bar closed, also when the pool threw
    try {
      report();
    } catch (...) {
      progress.reporter.attr("close")();
      throw;
    }
    progress.reporter.attr("close")();
  }
  return done.get();
}

constexpr EnumName<io::ColumnType> kColumnTypeNames[] = {
    {io::ColumnType::kInteger, "integer"},
    {io::ColumnType::kReal, "real"},
    {io::ColumnType::kText, "text"},
};

const char* type_name(io::ColumnType t) { return name_of(kColumnTypeNames, t, "text"); }

// rows as numpy arrays, one per column of a study's table, of the column's type: int64, float64
// (a value the CSV leaves empty, not finite, is nan) or str objects
template <class Values>
py::dict typed_arrays(const std::vector<io::ColumnInfo>& info, std::size_t rows, Values values) {
  const auto n = static_cast<py::ssize_t>(rows);
  std::vector<py::array> arrays;
  for (const io::ColumnInfo& c : info) {
    if (c.type == io::ColumnType::kInteger) arrays.emplace_back(py::array_t<long long>(n));
    if (c.type == io::ColumnType::kReal) arrays.emplace_back(py::array_t<double>(n));
    if (c.type == io::ColumnType::kText) {
      arrays.emplace_back(py::array(py::dtype("O"), std::vector<py::ssize_t>{n}));
    }
  }
  for (py::ssize_t i = 0; i < n; ++i) {
    const std::vector<io::FieldValue> v = values(static_cast<std::size_t>(i));
    for (std::size_t k = 0; k < info.size(); ++k) {
      if (const auto* x = std::get_if<long long>(&v[k])) {
        arrays[k].mutable_unchecked<long long, 1>()(i) = *x;
      } else if (const auto* d = std::get_if<double>(&v[k])) {
        arrays[k].mutable_unchecked<double, 1>()(i) =
            std::isfinite(*d) ? *d : std::numeric_limits<double>::quiet_NaN();
      } else {
        // object arrays hold references: set through the Python protocol
        arrays[k][py::int_(i)] = py::str(std::get<std::string>(v[k]));
      }
    }
  }
  py::dict out;
  for (std::size_t k = 0; k < info.size(); ++k) out[py::str(info[k].name)] = arrays[k];
  return out;
}

py::dict sweep_arrays(const study::SweepSpec& spec, const std::vector<study::SweepRow>& rows) {
  return typed_arrays(io::sweep_column_info(spec), rows.size(),
                      [&](std::size_t i) { return io::sweep_values(spec, rows[i]); });
}

py::dict spectrum_arrays(const study::SpectrumResult& res, double g) {
  return typed_arrays(io::spectrum_column_info(res.sliding, res.units), res.cells.size(),
                      [&](std::size_t i) { return io::spectrum_values(res, res.cells[i], g); });
}

py::dict boundary_arrays(const study::SpectrumResult& res, bool normalized, double g) {
  return typed_arrays(io::boundary_column_info(res.units), res.boundary.size(), [&](std::size_t i) {
    return io::boundary_values(res, res.boundary[i], normalized, g);
  });
}

}  // namespace

void bind_study(py::module_& m) {
  using namespace flexrock::study;

  py::enum_<Outcome> outcomes(m, "Outcome");
  for (const EnumName<Outcome>& row : kOutcomeNames) outcomes.value(row.name, row.value);
  py::enum_<Regime>(m, "Regime", "What the base did: slid and/or uplifted (finite friction).")
      .value("none", Regime::kNone)
      .value("sliding", Regime::kSliding)
      .value("rocking", Regime::kRocking)
      .value("sliding_rocking", Regime::kSlidingRocking);
  m.def("overturned", static_cast<bool (*)(Outcome)>(&overturned), py::arg("outcome"),
        R"doc(Whether an outcome is one of the two overturning classes.

Parameters
----------
outcome : Outcome

Returns
-------
bool)doc");

  FieldPickle<RunSummary>(
      py::class_<RunSummary>(m, "RunSummary", "What a study keeps of one simulation."))
      .def_readonly("outcome", &RunSummary::outcome)
      .def_readonly("status", &RunSummary::status)
      .def_readonly("max_theta_over_alpha", &RunSummary::max_theta_over_alpha)
      .def_readonly("max_theta", &RunSummary::max_theta)
      .def_readonly("impacts", &RunSummary::impacts)
      .def_readonly("first_uplift_time", &RunSummary::first_uplift_time)
      .def_readonly("overturn_time", &RunSummary::overturn_time)
      .def_readonly("overturn_edge", &RunSummary::overturn_edge)
      .def_readonly("max_impulse", &RunSummary::max_impulse)
      .def_readonly("energy_lost", &RunSummary::energy_lost)
      .def_readonly("max_friction_demand", &RunSummary::max_friction_demand)
      .def_readonly("max_uplift", &RunSummary::max_uplift)
      .def_readonly("t_end", &RunSummary::t_end)
      .def_readonly("max_offset", &RunSummary::max_offset)
      .def_readonly("final_offset", &RunSummary::final_offset)
      .def_readonly("sliding_time", &RunSummary::sliding_time)
      .def_readonly("slips", &RunSummary::slips)
      .def_readonly("regime", &RunSummary::regime)
      .def_readonly("tension_episodes", &RunSummary::tension_episodes, "pivot_tension events")
      .def_readonly("max_pivot_pull", &RunSummary::max_pivot_pull,
                    "[N] largest pull of the floor on a held pivot (0: none)")
      .def_readonly("tension_time", &RunSummary::tension_time,
                    "[s] time the floor pulled on a held pivot")
      .def_readonly("tensile_landings", &RunSummary::tensile_landings,
                    "landings that needed a pulling impulse")
      .def_readonly("max_tensile_impulse", &RunSummary::max_tensile_impulse,
                    "[N s] largest pulling impulse of a landing (0: none)")
      .pickled();
  m.def("summarize", &summarize, py::arg("body"), py::arg("result"),
        R"doc(The study outcome class and peaks of a finished simulation.

Parameters
----------
body : Body
result : SimulationResult

Returns
-------
RunSummary)doc");

  // spectra
  py::class_<GridUnits>(m, "GridUnits",
                        "The units a physical spectrum grid is given in: its cells and boundary "
                        "keep them and get columns in them (a_p_g, f_p_hz).")
      .def(py::init<>())
      .def(py::init([](std::string amplitude, double amplitude_si, std::string frequency,
                       double frequency_si) {
             return GridUnits{std::move(amplitude), amplitude_si, std::move(frequency),
                              frequency_si};
           }),
           py::arg("amplitude"), py::arg("amplitude_si"), py::arg("frequency"),
           py::arg("frequency_si"))
      .def_readwrite("amplitude", &GridUnits::amplitude, "\"m/s^2\", \"g\" or \"cm/s^2\"")
      .def_readwrite("amplitude_si", &GridUnits::amplitude_si, "[m/s^2] one amplitude unit")
      .def_readwrite("frequency", &GridUnits::frequency, "\"rad/s\" or \"Hz\"")
      .def_readwrite("frequency_si", &GridUnits::frequency_si, "[rad/s] one frequency unit")
      .def("__repr__", [](const GridUnits& u) {
        return "<GridUnits " + u.amplitude + ", " + u.frequency + ">";
      });
  py::class_<SpectrumSpec>(m, "SpectrumSpec", "A pulse spectrum: pulse x amplitude x frequency.")
      .def(py::init<>())
      .def_readwrite("pulse", &SpectrumSpec::pulse)
      .def_readwrite("normalized", &SpectrumSpec::normalized)
      .def_readwrite("amplitudes", &SpectrumSpec::amplitudes)
      .def_readwrite("frequencies", &SpectrumSpec::frequencies)
      .def_readwrite("units", &SpectrumSpec::units,
                     "physical axes: the units of amplitudes and frequencies (GridUnits)")
      .def_readwrite("free_periods", &SpectrumSpec::free_periods)
      .def_readwrite("bisect", &SpectrumSpec::bisect)
      .def_readwrite("bisection_tolerance", &SpectrumSpec::bisection_tolerance)
      .def_readwrite("solver", &SpectrumSpec::solver);
  py::class_<RecordSpectrumSpec>(m, "RecordSpectrumSpec", "One record x scale factors.")
      .def(py::init<>())
      .def_readwrite("motion", &RecordSpectrumSpec::motion)
      .def_readwrite("scales", &RecordSpectrumSpec::scales)
      .def_readwrite("free_periods", &RecordSpectrumSpec::free_periods)
      .def_readwrite("bisect", &RecordSpectrumSpec::bisect)
      .def_readwrite("bisection_tolerance", &RecordSpectrumSpec::bisection_tolerance)
      .def_readwrite("solver", &RecordSpectrumSpec::solver);
  py::class_<SpectrumCell>(m, "SpectrumCell")
      .def_readonly("row", &SpectrumCell::row)
      .def_readonly("column", &SpectrumCell::column)
      .def_readonly("amplitude", &SpectrumCell::amplitude)
      .def_readonly("frequency", &SpectrumCell::frequency)
      .def_readonly("amplitude_si", &SpectrumCell::amplitude_si)
      .def_readonly("omega_si", &SpectrumCell::omega_si)
      .def_readonly("computed", &SpectrumCell::computed)
      .def_readonly("run", &SpectrumCell::run);
  py::class_<OverturnBoundary> boundary(m, "OverturnBoundary");
  py::enum_<OverturnBoundary::Kind>(boundary, "Kind")
      .value("found", OverturnBoundary::Kind::kFound)
      .value("below_grid", OverturnBoundary::Kind::kBelowGrid)
      .value("none", OverturnBoundary::Kind::kNone);
  boundary.def_readonly("column", &OverturnBoundary::column)
      .def_readonly("frequency", &OverturnBoundary::frequency)
      .def_readonly("kind", &OverturnBoundary::kind)
      .def_readonly("safe", &OverturnBoundary::safe)
      .def_readonly("overturning", &OverturnBoundary::overturning)
      .def_readonly("bisection_runs", &OverturnBoundary::bisection_runs)
      .def_readonly("computed", &OverturnBoundary::computed)
      .def_readonly("mode", &OverturnBoundary::mode);
  // dynamic_attr: the Python package notes the units a spectrum was asked for
  py::class_<SpectrumResult>(m, "SpectrumResult", py::dynamic_attr(),
                             "Every cell of a spectrum and the minimum overturning of each column.")
      .def_readonly("alpha", &SpectrumResult::alpha)
      .def_readonly("tan_alpha", &SpectrumResult::tan_alpha)
      .def_readonly("p", &SpectrumResult::p)
      .def_readonly("cells", &SpectrumResult::cells)
      .def_readonly("boundary", &SpectrumResult::boundary)
      .def_readonly("sliding", &SpectrumResult::sliding)
      .def_readonly("units", &SpectrumResult::units,
                    "the units a physical grid was given in (SI otherwise)")
      .def("__repr__", [](const SpectrumResult& r) {
        std::size_t rows = 0, cols = 0, over = 0;
        for (const SpectrumCell& c : r.cells) {
          rows = std::max(rows, c.row + 1);
          cols = std::max(cols, c.column + 1);
          if (overturned(c.run.outcome)) ++over;
        }
        std::ostringstream o;
        o << "<SpectrumResult " << rows << " x " << cols << " cells (" << over << " overturned), "
          << r.boundary.size() << " boundary column(s), alpha = " << r.alpha << " rad, p = " << r.p
          << " rad/s>";
        return o.str();
      });
  m.def(
      "compute_spectrum",
      [](const Body& body, const SpectrumSpec& spec, int threads, const py::object& progress,
         const py::object& callback) {
        return interruptible(
            threads, [&](const study::RunOptions& o) { return compute_spectrum(body, spec, o); },
            progress_of(progress, callback, "spectrum",
                        spec.amplitudes.size() * spec.frequencies.size()));
      },
      py::arg("body"), py::arg("spec"), py::arg("threads") = 0, py::kw_only(),
      py::arg("progress") = py::bool_(true), py::arg("callback") = py::none(),
      R"doc(Every cell of a pulse spectrum, then the minimum overturning amplitude of each column.

Parameters
----------
body : Body
spec : SpectrumSpec
    Amplitudes and frequencies normalised (a_p/(g tan alpha), omega_p/p) or in m/s^2 and rad/s.
threads : int
    0: every core. The GIL is released.
progress : bool
    A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
    a plain line otherwise); False: none.
callback : callable, optional
    Called as callback(done, total) on the calling thread while the cells go (every 20 ms at
    most, when the count moved) and once at the end: for a notebook's own display. An
    exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

Returns
-------
SpectrumResult)doc");
  m.def(
      "compute_record_spectrum",
      [](const Body& body, const RecordSpectrumSpec& spec, int threads, const py::object& progress,
         const py::object& callback) {
        return interruptible(
            threads,
            [&](const study::RunOptions& o) { return compute_record_spectrum(body, spec, o); },
            progress_of(progress, callback, "record spectrum", spec.scales.size()));
      },
      py::arg("body"), py::arg("spec"), py::arg("threads") = 0, py::kw_only(),
      py::arg("progress") = py::bool_(true), py::arg("callback") = py::none(),
      R"doc(One record times scale factors, and the minimum overturning scale.

Parameters
----------
body : Body
spec : RecordSpectrumSpec
threads : int
    0: every core.
progress : bool
    A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
    a plain line otherwise); False: none.
callback : callable, optional
    Called as callback(done, total) on the calling thread while the runs go (every 20 ms at
    most, when the count moved) and once at the end: for a notebook's own display. An
    exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

Returns
-------
SpectrumResult)doc");
  m.def("run_pulse_cell", &run_pulse_cell, py::arg("body"), py::arg("spec"), py::arg("a_p"),
        py::arg("omega_p"), py::call_guard<py::gil_scoped_release>(),
        R"doc(One pulse-spectrum cell, as compute_spectrum runs it.

Parameters
----------
body : Body
spec : SpectrumSpec
a_p : float
    [m/s^2] amplitude.
omega_p : float
    [rad/s] frequency.

Returns
-------
RunSummary)doc");
  m.def("run_record_cell", &run_record_cell, py::arg("body"), py::arg("spec"), py::arg("scale"),
        py::call_guard<py::gil_scoped_release>(), R"doc(One record-spectrum cell.

Parameters
----------
body : Body
spec : RecordSpectrumSpec
scale : float
    [-] factor on the record.

Returns
-------
RunSummary)doc");
  m.def("pulse_motion", &pulse_motion, py::arg("type"), py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), R"doc(A pulse of a family as a ground motion.

Parameters
----------
type : str
    A pulse type of spectra (``spectrum_pulse_names()``).
a_p : float
    [m/s^2]
omega_p : float
    [rad/s]
duration : float
    [s]

Returns
-------
GroundMotion)doc");
  m.def("pulse_length", &pulse_length, py::arg("type"), py::arg("omega_p"),
        R"doc(The length of one pulse of a family.

Parameters
----------
type : str
    A pulse type of spectra (``spectrum_pulse_names()``).
omega_p : float
    [rad/s]

Returns
-------
float
    [s])doc");

  // sweeps
  py::class_<Intensity>(m, "Intensity")
      .def_readonly("pga", &Intensity::pga, "[m/s^2]")
      .def_readonly("pgv", &Intensity::pgv, "[m/s]")
      .def_readonly("measures", &Intensity::measures, "[SI] the requested measures, in order");
  py::class_<MeasureRequest>(m, "MeasureRequest")
      .def(py::init([](std::string name, double period, double zeta, std::string unit) {
             return MeasureRequest{std::move(name), period, zeta, std::move(unit)};
           }),
           py::arg("name"), py::arg("period") = 0.0, py::arg("zeta") = 0.05, py::kw_only(),
           py::arg("unit") = "")
      .def_readwrite("name", &MeasureRequest::name, "a name of intensity_measures()")
      .def_readwrite("period", &MeasureRequest::period, "[s] sa only")
      .def_readwrite("zeta", &MeasureRequest::zeta, "[-] sa only")
      .def_readwrite("unit", &MeasureRequest::unit,
                     "sa only: \"\" or \"m/s^2\" (SI), \"g\" or \"cm/s^2\": its column's unit");
  m.def("measure_request", &measure_request, py::arg("text"),
        R"doc(A measure as the command line names it: a name of ``intensity_measures()`` or "sa:T",
"sa:T:zeta".

Parameters
----------
text : str

Returns
-------
MeasureRequest)doc");
  m.def(
      "intensity_measures",
      [] {
        py::list out;
        for (const IntensityMeasure& k : intensity_measures()) {
          py::dict d;
          d["name"] = k.name;
          d["column"] = k.column;
          d["unit"] = k.unit;
          d["doc"] = k.doc;
          d["scale_power"] = k.scale_power;
          d["needs_period"] = k.needs_period;
          out.append(d);
        }
        return out;
      },
      R"doc(The table of intensity measures (the one the sweep columns, ``flexrock fragility --im``
and the docs are written from).

Returns
-------
list of dict
    name, column (empty for sa: ``sa_T<T>_z<zeta>_m_per_s2``), unit, doc, scale_power (the value
    of the record scaled by s is s**scale_power times the value), needs_period.)doc");
  m.def("require_spectral_period", &require_spectral_period, py::arg("period"), py::arg("key"),
        R"doc(Raises InputError naming ``key`` unless ``period`` [s] is finite and at least 1e-6 s
(below it the oscillator follows the ground and Sa is the PGA).)doc");
  m.def(
      "intensity_measure",
      [](const std::string& name, const std::vector<double>& t, const std::vector<double>& a,
         double period, double zeta) {
        const IntensityMeasure* k = find_intensity_measure(name);
        if (!k) throw InputError("intensity measure '" + name + "': unknown");
        if (k->needs_period) require_spectral_period(period, "intensity_measure: period");
        return k->compute(t, a, period, zeta);
      },
      py::arg("name"), py::arg("t"), py::arg("a"), py::arg("period") = 0.0, py::arg("zeta") = 0.05,
      R"doc(One intensity measure of a record, a piecewise linear between its samples.

Parameters
----------
name : str
    A name of ``intensity_measures()``.
t : array of float
    [s] increasing sample times.
a : array of float
    [m/s^2] horizontal acceleration at the samples.
period, zeta : float
    [s] and [-]: only for ``sa``.

Returns
-------
float
    In the measure's SI unit.)doc");
  m.def(
      "rotd",
      [](const std::vector<double>& t, const std::vector<double>& a1, const std::vector<double>& a2,
         double period, double zeta) {
        RotD r;
        {
          py::gil_scoped_release nogil;
          r = rotd_spectral_acceleration(t, a1, a2, period, zeta);
        }
        py::dict d;
        d["rotd50"] = r.rotd50;
        d["rotd100"] = r.rotd100;
        d["by_angle"] =
            py::array_t<double>(static_cast<py::ssize_t>(r.by_angle.size()), r.by_angle.data());
        return d;
      },
      py::arg("t"), py::arg("a1"), py::arg("a2"), py::arg("period"), py::arg("zeta") = 0.05,
      R"doc(RotD50 and RotD100 of two orthogonal horizontal components (Boore 2010): for each
rotation angle 0, 1, ..., 179 deg the pseudo-spectral acceleration of a1 cos + a2 sin (as
``intensity_measure("sa", ...)``); RotD50 the median over the angles, RotD100 the largest.

Parameters
----------
t : array of float
    [s] increasing sample times, shared by both components.
a1, a2 : array of float
    [m/s^2] the two horizontal components at the samples.
period, zeta : float
    [s] natural period of the oscillator, [-] its damping ratio.

Returns
-------
dict
    ``rotd50``, ``rotd100`` [m/s^2] and ``by_angle`` (numpy array of 180 values, m/s^2).)doc");
  m.def("intensity",
        py::overload_cast<const GroundMotion&, const std::vector<MeasureRequest>&, double>(
            &intensity),
        py::arg("motion"), py::arg("measures") = std::vector<MeasureRequest>{},
        py::arg("analytic_dt") = 1e-3,
        R"doc(Peak ground acceleration and velocity of a motion's horizontal component.

Parameters
----------
motion : GroundMotion
measures : list of MeasureRequest
    Further measures, written to ``Intensity.measures`` in this order.
analytic_dt : float
    [s] sampling of an analytic motion (plus its breakpoints).

Returns
-------
Intensity
    pga [m/s^2], pgv [m/s] (trapezoidal integral from 0), measures.)doc");
  py::class_<SweepBody>(m, "SweepBody")
      .def(py::init([](std::string name, BodyParameters body) {
             return SweepBody{std::move(name), std::move(body)};
           }),
           py::arg("name"), py::arg("body"))
      .def_readwrite("name", &SweepBody::name)
      .def_readwrite("body", &SweepBody::body)
      .def_readwrite("friction_coefficient", &SweepBody::friction_coefficient,
                     "this body's static friction coefficient in place of the solver's (None: "
                     "the solver's)")
      .def_readwrite("kinetic_friction_coefficient", &SweepBody::kinetic_friction_coefficient,
                     "its kinetic one (None or inf: equal to the static one)");
  py::class_<SweepRecord>(m, "SweepRecord")
      .def(py::init([](std::string name, GroundMotion motion) {
             return SweepRecord{std::move(name), std::move(motion), nullptr};
           }),
           py::arg("name"), py::arg("motion"))
      .def_readwrite("name", &SweepRecord::name)
      .def_readwrite("motion", &SweepRecord::motion);
  py::enum_<ScaleKind>(m, "ScaleKind")
      .value("factor", ScaleKind::kFactor)
      .value("target_pga", ScaleKind::kTargetPga)
      .value("target_measure", ScaleKind::kTargetMeasure);
  py::class_<SweepSpec>(m, "SweepSpec", "Bodies x records x scale factors.")
      .def(py::init<>())
      .def_readwrite("bodies", &SweepSpec::bodies)
      .def_readwrite("records", &SweepSpec::records)
      .def_readwrite("scale_kind", &SweepSpec::scale_kind)
      .def_readwrite("scales", &SweepSpec::scales)
      .def_readwrite("free_periods", &SweepSpec::free_periods)
      .def_readwrite("solver", &SweepSpec::solver)
      .def_readwrite("target", &SweepSpec::target,
                     "the measure scale_kind target_measure scales to (MeasureRequest)")
      .def_readwrite("measures", &SweepSpec::measures,
                     "intensity measures every row gets besides PGA and PGV (MeasureRequest)")
      .def_readwrite("levels", &SweepSpec::levels,
                     "the levels as requested (CSV column requested_level); empty: scales")
      .def_readwrite("level_units", &SweepSpec::level_units,
                     "units of target-PGA levels: \"g\", \"m/s^2\" or \"cm/s^2\"")
      .def_readwrite("uncertainty", &SweepSpec::uncertainty,
                     "parameters each run samples (Uncertainty; empty: none)");
  py::class_<SweepRow>(m, "SweepRow")
      .def_readonly("index", &SweepRow::index)
      .def_readonly("body", &SweepRow::body)
      .def_readonly("record", &SweepRow::record)
      .def_readonly("scale_index", &SweepRow::scale_index)
      .def_readonly("scale", &SweepRow::scale)
      .def_readonly("pga", &SweepRow::pga)
      .def_readonly("pgv", &SweepRow::pgv)
      .def_readonly("measures", &SweepRow::measures, "[SI] the requested measures, scaled")
      .def_readonly("duration", &SweepRow::duration)
      .def_readonly("message", &SweepRow::message)
      .def_readonly("run", &SweepRow::run)
      .def_readonly("sampled", &SweepRow::sampled,
                    "the run's values of spec.uncertainty, in its order");
  m.def(
      "run_sweep",
      [](const SweepSpec& spec, const std::vector<std::size_t>& indices, int threads,
         const py::object& progress, const py::object& callback) {
        const std::size_t total = indices.empty() ? study::sweep_runs(spec).size() : indices.size();
        return interruptible(
            threads, [&](const study::RunOptions& o) { return run_sweep(spec, indices, o); },
            progress_of(progress, callback, "sweep", total));
      },
      py::arg("spec"), py::arg("indices") = std::vector<std::size_t>{}, py::arg("threads") = 0,
      py::kw_only(), py::arg("progress") = py::bool_(true), py::arg("callback") = py::none(),
      R"doc(Runs a sweep (bodies x records x scales), or the given run indices.

Parameters
----------
spec : SweepSpec
indices : list of int
    Empty: every run.
threads : int
    0: every core. The GIL is released.
progress : bool
    A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
    a plain line otherwise); False: none.
callback : callable, optional
    Called as callback(done, total) on the calling thread while the runs go (every 20 ms at
    most, when the count moved) and once at the end: for a notebook's own display. An
    exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

Returns
-------
list of SweepRow
    In index order.)doc");

  // fragility
  FieldPickle<FragilityFit>(
      py::class_<FragilityFit>(m, "FragilityFit", "Lognormal fragility P = Phi(ln(x/theta)/beta)."))
      .def_readonly("theta", &FragilityFit::theta)
      .def_readonly("beta", &FragilityFit::beta)
      .def_readonly("se_ln_theta", &FragilityFit::se_ln_theta)
      .def_readonly("se_beta", &FragilityFit::se_beta)
      .def_readonly("cov_ln_theta_beta", &FragilityFit::cov_ln_theta_beta)
      .def_readonly("confidence", &FragilityFit::confidence)
      .def_readonly("theta_lower", &FragilityFit::theta_lower)
      .def_readonly("theta_upper", &FragilityFit::theta_upper)
      .def_readonly("beta_lower", &FragilityFit::beta_lower)
      .def_readonly("beta_upper", &FragilityFit::beta_upper)
      .def_property_readonly("cov_ab",
                             [](const FragilityFit& f) {
                               return py::make_tuple(f.cov_ab[0], f.cov_ab[1], f.cov_ab[2]);
                             })
      .field(
          "cov_ab",
          [](const FragilityFit& f) {
            return std::array<double, 3>{f.cov_ab[0], f.cov_ab[1], f.cov_ab[2]};
          },
          [](FragilityFit& f, const py::handle& v) {
            const auto a = v.cast<std::array<double, 3>>();
            std::copy(a.begin(), a.end(), f.cov_ab);
          })
      .def_readonly("log_likelihood", &FragilityFit::log_likelihood)
      .def_readonly("iterations", &FragilityFit::iterations)
      .def_readonly("samples", &FragilityFit::samples)
      .def_readonly("failures", &FragilityFit::failures)
      .def("__repr__",
           [](const FragilityFit& f) {
             std::ostringstream o;
             o.precision(4);
             o << "<FragilityFit theta = " << f.theta << " [" << f.theta_lower << ", "
               << f.theta_upper << "], beta = " << f.beta << " [" << f.beta_lower << ", "
               << f.beta_upper << "] (" << 100.0 * f.confidence << "% bounds), " << f.failures
               << " failures in " << f.samples << " runs>";
             return o.str();
           })
      .pickled();
  m.def("fit_lognormal", &fit_lognormal, py::arg("im"), py::arg("failed"),
        py::arg("confidence") = 0.95,
        R"doc(Maximum-likelihood lognormal fragility P(failure | IM = x) = Phi(ln(x/theta)/beta).

Parameters
----------
im : list of float
    Intensity measures, > 0 (theta comes out in their unit).
failed : list of int
    0 or 1 per run.
confidence : float
    Level of the bounds, in (0, 1).

Returns
-------
FragilityFit)doc");
  m.def(
      "fit_stripes",
      [](const std::vector<double>& im, const std::vector<std::size_t>& runs,
         const std::vector<std::size_t>& failures, double confidence) {
        if (im.size() != runs.size() || im.size() != failures.size())
          throw InputError("fit_stripes: expected as many runs and failures as stripe IMs");
        std::vector<Stripe> s;
        for (std::size_t j = 0; j < im.size(); ++j) s.push_back({im[j], runs[j], failures[j]});
        return fit_stripes(s, confidence);
      },
      py::arg("im"), py::arg("runs"), py::arg("failures"), py::arg("confidence") = 0.95,
      R"doc(Multiple-stripe analysis: the binomial maximum-likelihood lognormal fragility (Baker
2015), as ``flexrock fragility --analysis msa`` fits it.

Parameters
----------
im : list of float
    The stripes' intensity measures, > 0, distinct.
runs, failures : list of int
    Runs at each stripe, and how many of them failed.
confidence : float
    Level of the bounds, in (0, 1).

Returns
-------
FragilityFit
    log_likelihood includes the binomial coefficients.)doc");
  m.def(
      "capacity_intervals",
      [](const std::vector<double>& im, const std::vector<int>& failed,
         const std::vector<std::string>& record) {
        std::vector<double> lower, upper;
        for (const CapacityInterval& c : capacity_intervals(im, failed, record)) {
          lower.push_back(c.lower);
          upper.push_back(c.upper);
        }
        return py::make_tuple(lower, upper);
      },
      py::arg("im"), py::arg("failed"), py::arg("record"),
      R"doc(Each record's capacity interval (lower, upper] from an incremental dynamic analysis.

Parameters
----------
im, failed, record : lists
    One IM, outcome (0/1) and record name per run.

Returns
-------
(list of float, list of float)
    lower (0: failed at its lowest run) and upper (inf: never failed, truncated at lower), one
    per record in order of first appearance.)doc");
  m.def(
      "fit_capacity_intervals",
      [](const std::vector<double>& lower, const std::vector<double>& upper, double confidence) {
        if (lower.size() != upper.size())
          throw InputError("fit_capacity_intervals: expected as many upper as lower bounds");
        std::vector<CapacityInterval> c;
        for (std::size_t i = 0; i < lower.size(); ++i) c.push_back({lower[i], upper[i]});
        return fit_capacity_intervals(c, confidence);
      },
      py::arg("lower"), py::arg("upper"), py::arg("confidence") = 0.95,
      R"doc(Lognormal fit of capacities known to lie in (lower, upper] (upper inf: truncated;
lower == upper: exact), by maximum likelihood, as ``flexrock fragility --analysis ida`` fits it.

Parameters
----------
lower, upper : list of float
confidence : float

Returns
-------
FragilityFit
    samples: records, failures: records with a finite upper bound.)doc");
  m.def("crossing_intensity", &crossing_intensity, py::arg("a"), py::arg("b"),
        R"doc(The IM at which two fitted fragility curves cross (nan for equal betas).

Parameters
----------
a, b : FragilityFit

Returns
-------
float)doc");
  m.def(
      "fragility_probability",
      [](const FragilityFit& fit,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& x) -> py::object {
        py::array_t<double> p(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()));
        const double* in = x.data();
        double* out = p.mutable_data();
        for (py::ssize_t i = 0; i < x.size(); ++i) out[i] = fragility_probability(fit, in[i]);
        if (x.ndim() == 0) return py::float_(out[0]);
        return p;
      },
      py::arg("fit"), py::arg("x"),
      R"doc(The fitted probability of failure P(failure | IM = x) = Phi(ln(x/theta)/beta).

Parameters
----------
fit : FragilityFit
x : float or array_like
    Intensity measure, in the units of the IM the fit was made with (e.g. [g] for pga_g);
    arrays of any shape broadcast elementwise. x <= 0 gives 0.

Returns
-------
float or numpy.ndarray
    [-] of the shape of ``x``.)doc");
  m.def(
      "fragility_band",
      [](const FragilityFit& fit,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& x) -> py::object {
        const std::vector<py::ssize_t> shape(x.shape(), x.shape() + x.ndim());
        py::array_t<double> lo(shape), hi(shape);
        const double* in = x.data();
        double* l = lo.mutable_data();
        double* u = hi.mutable_data();
        for (py::ssize_t i = 0; i < x.size(); ++i) fragility_band(fit, in[i], l[i], u[i]);
        if (x.ndim() == 0) return py::make_tuple(l[0], u[0]);
        return py::make_tuple(lo, hi);
      },
      py::arg("fit"), py::arg("x"),
      R"doc(The pointwise confidence band of the fitted curve (delta method).

Parameters
----------
fit : FragilityFit
    Its ``confidence`` is the level of the band.
x : float or array_like
    Intensity measure in the fit's units; arrays of any shape broadcast elementwise.

Returns
-------
(lower, upper) : tuple of float or of numpy.ndarray
    [-] probabilities, each of the shape of ``x``.)doc");
  m.def("lognormal_log_likelihood", &lognormal_log_likelihood, py::arg("im"), py::arg("failed"),
        py::arg("theta"), py::arg("beta"),
        R"doc(The log-likelihood of lognormal fragility parameters.

Parameters
----------
im : list of float
    Intensity measures, > 0.
failed : list of int
    0 or 1.
theta : float
    Median, in the IM's unit.
beta : float
    [-] lognormal standard deviation.

Returns
-------
float)doc");

  // study files
  py::class_<io::SpectrumFile>(m, "SpectrumFile", "A spectrum spec file, loaded and checked.")
      .def_readonly("source", &io::SpectrumFile::source)
      .def_readonly("name", &io::SpectrumFile::name)
      .def_readonly("body_source", &io::SpectrumFile::body_source)
      .def_readonly("body", &io::SpectrumFile::body)
      .def_readonly("is_record", &io::SpectrumFile::is_record)
      .def_readonly("pulse", &io::SpectrumFile::pulse)
      .def_readonly("record", &io::SpectrumFile::record)
      .def_readonly("record_name", &io::SpectrumFile::record_name);
  m.def("load_spectrum_file", &io::load_spectrum_file, py::arg("path"),
        R"doc(Reads and checks a spectrum file (TOML, docs/studies.md).

Parameters
----------
path : str

Returns
-------
SpectrumFile
    Grids as given: normalised, or in the units of ``pulse.units``.)doc");
  m.def("spectrum_columns", &io::spectrum_columns, py::arg("sliding") = false,
        py::arg("units") = GridUnits{},
        R"doc(Columns of the spectrum CSV (unit-suffixed).

Parameters
----------
sliding : bool
    With the sliding columns (regime, offsets, time sliding, slips) that a spectrum with a
    finite friction coefficient adds (``SpectrumResult.sliding``).
units : GridUnits
    A physical grid's units (``SpectrumResult.units``): units other than SI add columns in them
    (``a_p_g``, ``f_p_hz``).

Returns
-------
list of str)doc");
  m.def("boundary_columns", &io::boundary_columns, py::arg("units") = GridUnits{},
        R"doc(Columns of the minimum-overturning CSV.

Parameters
----------
units : GridUnits
    As for :func:`spectrum_columns` (``min_overturning_g``, ``f_p_hz``).

Returns
-------
list of str)doc");
  m.def(
      "spectrum_csv",
      [](const SpectrumResult& r, double g) {
        std::ostringstream out;
        io::write_spectrum_csv(out, r, g);
        return out.str();
      },
      py::arg("result"), py::arg("g"), R"doc(The spectrum CSV text (one row per cell).

Parameters
----------
result : SpectrumResult
g : float
    [m/s^2] gravity for the normalised columns.

Returns
-------
str)doc");
  m.def(
      "boundary_csv",
      [](const SpectrumResult& r, bool normalized, double g) {
        std::ostringstream out;
        io::write_boundary_csv(out, r, normalized, g);
        return out.str();
      },
      py::arg("result"), py::arg("normalized"), py::arg("g"),
      R"doc(The minimum-overturning CSV text (one row per frequency column).

Parameters
----------
result : SpectrumResult
normalized : bool
    Whether the spectrum's grid was normalised (the units of ``frequency``, ``min_overturning``).
g : float
    [m/s^2]

Returns
-------
str)doc");

  py::class_<io::SweepManifest>(m, "SweepManifest")
      .def_readonly("source", &io::SweepManifest::source)
      .def_readonly("spec", &io::SweepManifest::spec)
      .def_readonly("hash", &io::SweepManifest::hash);
  m.def("load_sweep_manifest", &io::load_sweep_manifest, py::arg("path"),
        R"doc(Reads and checks a sweep manifest (TOML, docs/studies.md).

Parameters
----------
path : str

Returns
-------
SweepManifest
    Its spec (target PGAs in m/s^2, the levels as written in ``spec.levels``) and hash.)doc");
  m.def("sweep_columns", py::overload_cast<bool>(&io::sweep_columns), py::arg("sliding") = false,
        R"doc(Columns of the sweep CSV.

Parameters
----------
sliding : bool
    With the sliding columns that a sweep with a finite friction coefficient adds
    (``sweep_has_friction(spec)``).

Returns
-------
list of str
    index, body, record, requested_level, requested_units, scale, pga_m_per_s2, pga_g, ...)doc");
  m.def("sweep_has_friction", &has_friction, py::arg("spec"),
        R"doc(Whether any run of a sweep has a finite friction coefficient (its rows then end
with the sliding columns).

Parameters
----------
spec : SweepSpec

Returns
-------
bool)doc");
  m.def("sweep_spec_columns", py::overload_cast<const SweepSpec&>(&io::sweep_columns),
        py::arg("spec"),
        R"doc(Columns of a spec's sweep CSV: the requested intensity measures after pgv_m_per_s, the
sliding columns if it has friction.

Parameters
----------
spec : SweepSpec

Returns
-------
list of str)doc");
  m.def("sweep_row", &io::sweep_row, py::arg("spec"), py::arg("row"),
        R"doc(One line of the sweep CSV (no line end).

Parameters
----------
spec : SweepSpec
row : SweepRow

Returns
-------
str)doc");

  m.def(
      "sweep_column_info",
      [](const SweepSpec& spec) {
        py::list out;
        for (const io::ColumnInfo& c : io::sweep_column_info(spec)) {
          out.append(py::dict(py::arg("name") = c.name, py::arg("unit") = c.unit,
                              py::arg("type") = type_name(c.type)));
        }
        return out;
      },
      py::arg("spec"),
      R"doc(The columns of a spec's sweep CSV as the table declares them.

Parameters
----------
spec : SweepSpec

Returns
-------
list of dict
    ``{"name", "unit", "type"}``, type "integer", "real" or "text" (the dtype of the column's
    array in :func:`sweep_arrays`: int64, float64, object).)doc");
  m.def("sweep_arrays", &sweep_arrays, py::arg("spec"), py::arg("rows"),
        R"doc(Rows of a sweep as numpy arrays, one per column of its CSV, typed by the column table.

Parameters
----------
spec : SweepSpec
rows : list of SweepRow

Returns
-------
dict of str to numpy.ndarray
    int64 for indices and counts, float64 for reals (nan where the CSV leaves the field empty),
    object (str) for names and classes.)doc");
  m.def("boundary_arrays", &boundary_arrays, py::arg("result"), py::arg("normalized") = true,
        py::arg("g") = 9.80665,
        R"doc(The boundary CSV's columns as numpy arrays of their types, from the result itself (no
CSV text): int64, float64 (nan where the CSV is empty) and str objects.

Parameters
----------
result : SpectrumResult
normalized : bool
    The grid's axes (``min_overturning`` in a_p/(g tan alpha), else in m/s^2).
g : float
    [m/s^2]

Returns
-------
dict of str to numpy.ndarray)doc");
  m.def(
      "spectrum_arrays", &spectrum_arrays, py::arg("result"), py::arg("g") = 9.80665,
      R"doc(The cells of a spectrum as numpy arrays, one per column of its CSV, typed by the column
table (the columns of ``spectrum_columns(result.sliding)``).

Parameters
----------
result : SpectrumResult
g : float
    [m/s^2] the body's gravity, as for the CSV.

Returns
-------
dict of str to numpy.ndarray
    int64 for indices and counts, float64 for reals (nan where the CSV leaves the field empty),
    object (str) for classes.)doc");
  m.def("read_sweep_csv", &io::read_sweep_csv, py::arg("spec"), py::arg("path"),
        R"doc(A sweep CSV read back as the rows it was written from (every line checked against its
run: it must be exactly what the row writes).

Parameters
----------
spec : SweepSpec
path : str

Returns
-------
list of SweepRow
    In index order.)doc");
  py::class_<io::SweepSession>(m, "SweepSession", R"doc(A sweep from its manifest to its CSV.

Opening it checks every run and opens (or resumes) the journal ``output + ".partial"``, the one
``flexrock sweep`` keeps: a sweep the command line started and that was interrupted goes on here,
and the CSV has the same bytes as an uninterrupted run.)doc")
      .def(py::init([](io::SweepManifest manifest, std::string output) {
             return std::make_unique<io::SweepSession>(std::move(manifest), std::move(output));
           }),
           py::arg("manifest"), py::arg("output"))
      .def_property_readonly("runs", &io::SweepSession::runs)
      .def_property_readonly("resumed", &io::SweepSession::resumed,
                             "runs finished before this start (in the journal)")
      .def_property_readonly("remaining", &io::SweepSession::remaining)
      .def_property_readonly("output", &io::SweepSession::output)
      .def_property_readonly("journal_path", &io::SweepSession::journal_path)
      .def_property_readonly("manifest", &io::SweepSession::manifest)
      .def(
          "run",
          [](io::SweepSession& s, int threads, const py::object& progress,
             const py::object& callback) {
            interruptible(
                threads, [&](const study::RunOptions& o) { s.run(o); },
                progress_of(progress, callback, "sweep", s.share().size()));
          },
          py::arg("threads") = 0, py::kw_only(), py::arg("progress") = py::bool_(true),
          py::arg("callback") = py::none(),
          R"doc(Runs the runs left, journaling each as it finishes (the GIL is released).
Ctrl-C stops it between runs and raises KeyboardInterrupt; the journal keeps every finished run
and run() again, or a new session on the same manifest and output, goes on from there. Raises
RuntimeError after finish().

Parameters
----------
threads : int
    0: every core.
progress : bool
    A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
    a plain line otherwise); False: none.
callback : callable, optional
    Called as callback(done, total) (the runs left at the start) on the calling thread while the runs go (every 20 ms at
    most, when the count moved) and once at the end: for a notebook's own display. An
    exception it raises stops the runs between two, as Ctrl-C does, and is raised here.)doc")
      .def("finish", &io::SweepSession::finish, py::call_guard<py::gil_scoped_release>(),
           R"doc(Writes the CSV from every row and deletes the journal. Raises RuntimeError, the
journal kept, when a run is not finished (run() not called, or stopped): call run() first; and
when called again (the session is over).

Returns
-------
list of SweepRow
    Every run's row, in index order.)doc");

  py::class_<io::SpectrumSession>(m, "SpectrumSession",
                                  R"doc(A spectrum from its spec file to its CSVs.

Opening it checks every run and opens (or resumes) the journal ``output + ".partial"``, the one
``flexrock spectrum`` keeps: a spectrum the command line started and that was interrupted goes on
here, and the CSVs have the same bytes as an uninterrupted run.)doc")
      .def(py::init([](io::SpectrumFile file, std::string output, std::string boundary_output,
                       bool bisect) {
             if (!bisect) {
               // as the command line's --no-bisect
               file.pulse.bisect = false;
               file.record.bisect = false;
             }
             return std::make_unique<io::SpectrumSession>(std::move(file), std::move(output),
                                                          std::move(boundary_output));
           }),
           py::arg("file"), py::arg("output"), py::arg("boundary_output"), py::arg("bisect") = true)
      .def_property_readonly("cells", &io::SpectrumSession::cells)
      .def_property_readonly("runs", &io::SpectrumSession::runs, "cells and boundaries")
      .def_property_readonly("resumed", &io::SpectrumSession::resumed,
                             "cells and boundaries finished before this start (in the journal)")
      .def_property_readonly("bisect", &io::SpectrumSession::bisect)
      .def_property_readonly("journal_path", &io::SpectrumSession::journal_path)
      .def_property_readonly("grid", &io::SpectrumSession::grid)
      .def(
          "run",
          [](io::SpectrumSession& s, int threads, const py::object& progress,
             const py::object& callback) {
            interruptible(
                threads, [&](const study::RunOptions& o) { s.run(o); },
                progress_of(progress, callback, "spectrum", s.share_cells()));
          },
          py::arg("threads") = 0, py::kw_only(), py::arg("progress") = py::bool_(true),
          py::arg("callback") = py::none(),
          R"doc(Runs the cells and bisections left, journaling each as it finishes (the GIL is
released). Ctrl-C stops it between runs and raises KeyboardInterrupt; the journal keeps every
finished cell and boundary and run() again, or a new session on the same file and outputs, goes
on from there. Raises RuntimeError after finish().

Parameters
----------
threads : int
    0: every core.
progress : bool
    A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
    a plain line otherwise); False: none.
callback : callable, optional
    Called as callback(done, total) (cells left at the start; a bisection's runs come on top) on the calling thread while the runs go (every 20 ms at
    most, when the count moved) and once at the end: for a notebook's own display. An
    exception it raises stops the runs between two, as Ctrl-C does, and is raised here.)doc")
      .def(
          "finish", [](io::SpectrumSession& s) { return s.finish(); },
          py::call_guard<py::gil_scoped_release>(),
          R"doc(Writes the CSVs from every cell and boundary and deletes the journal. Raises
RuntimeError, the journal kept, when a cell or boundary is not finished (run() not called, or
stopped): call run() first; and when called again (the session is over).

Returns
-------
SpectrumResult
    Every cell and boundary, read back as data.)doc");

  py::class_<io::CsvTable>(m, "CsvTable")
      .def_readonly("source", &io::CsvTable::source)
      .def_readonly("columns", &io::CsvTable::columns)
      .def_readonly("rows", &io::CsvTable::rows);
  m.def("read_csv_table", &io::read_csv_table, py::arg("path"),
        R"doc(Reads a CSV file as text fields (a sweep CSV for a fragility fit).

Parameters
----------
path : str

Returns
-------
CsvTable)doc");
  py::class_<io::FragilityQuery>(m, "FragilityQuery")
      .def(py::init<>())
      .def_readwrite("im", &io::FragilityQuery::im)
      .def_readwrite("outcome", &io::FragilityQuery::outcome)
      .def_readwrite("level", &io::FragilityQuery::level)
      .def_readwrite("body", &io::FragilityQuery::body)
      .def_readwrite("worst_azimuth", &io::FragilityQuery::worst_azimuth,
                     "one observation per record pair and level: failed at any azimuth, its "
                     "measure the median over them (rotd50:<im>)");
  FieldPickle<io::FragilityData>(py::class_<io::FragilityData>(m, "FragilityData"))
      .def_readonly("body", &io::FragilityData::body)
      .def_readonly("im", &io::FragilityData::im)
      .def_readonly("failed", &io::FragilityData::failed)
      .def_readonly("excluded", &io::FragilityData::excluded)
      .def_readonly("record", &io::FragilityData::record)
      .def_readonly("im_name", &io::FragilityData::im_name,
                    "the intensity measure, as --im names it")
      .def_readonly("im_unit", &io::FragilityData::im_unit, "its unit")
      .pickled();
  m.def("fragility_data",
        py::overload_cast<const io::CsvTable&, const io::FragilityQuery&>(&io::fragility_data),
        py::arg("table"), py::arg("query"),
        R"doc(The (IM, failed) observations of each body of a sweep CSV.

Parameters
----------
table : CsvTable
query : FragilityQuery
    im: pga [m/s^2], pga_g [g], pgv [m/s], scale [-] or requested_level; outcome:
    overturned, theta or energy, with its level.

Returns
-------
list of FragilityData
    Rows whose outcome is stopped or contact_lost are left out and counted (``excluded``).)doc");
  // the fragility session: typed damage states, measures and analyses, as flexrock fragility
  py::enum_<io::FragilityOutcome> fo(m, "FragilityOutcome",
                                     "What a fragility fit counts as failure (--outcome).");
  for (const io::FragilityOutcomeInfo& o : io::kFragilityOutcomes) fo.value(o.name, o.outcome);
  py::class_<io::DamageState>(m, "DamageState", "A damage state: an outcome and its level.")
      .def(py::init([](io::FragilityOutcome outcome, double level, std::string label) {
             if (label.empty()) label = io::fragility_outcome(outcome).name;
             return io::DamageState{label, outcome, level};
           }),
           py::arg("outcome"), py::arg("level") = 0.0, py::arg("label") = "")
      .def_readonly("label", &io::DamageState::label)
      .def_readonly("outcome", &io::DamageState::outcome)
      .def_readonly("level", &io::DamageState::level)
      .def("__repr__", [](const io::DamageState& s) { return "<DamageState " + s.label + ">"; });
  m.def("damage_state", &io::damage_state, py::arg("text"),
        R"doc(A damage state as ``flexrock fragility --state`` reads it.

Parameters
----------
text : str
    overturned, uplift, theta:X, energy:X, offset:X or residual_offset:X (X > 0).

Returns
-------
DamageState)doc");
  py::enum_<io::FragilityMeasureKind>(m, "FragilityMeasureKind")
      .value("pga", io::FragilityMeasureKind::kPga)
      .value("pga_g", io::FragilityMeasureKind::kPgaG)
      .value("pgv", io::FragilityMeasureKind::kPgv)
      .value("scale", io::FragilityMeasureKind::kScale)
      .value("requested_level", io::FragilityMeasureKind::kRequestedLevel)
      .value("intensity", io::FragilityMeasureKind::kIntensity);
  py::class_<io::FragilityMeasure>(m, "FragilityMeasure",
                                   "An intensity measure of a fit: kind, sweep column, unit.")
      .def_readonly("kind", &io::FragilityMeasure::kind)
      .def_readonly("name", &io::FragilityMeasure::name)
      .def_readonly("column", &io::FragilityMeasure::column)
      .def_readonly("unit", &io::FragilityMeasure::unit);
  m.def("fragility_measure", &io::fragility_measure, py::arg("name"),
        R"doc(The intensity measure of a fit so named (``flexrock fragility --im``).

Parameters
----------
name : str
    pga, pga_g, pgv, scale, requested_level or a measure of the sweep's [intensity] table.

Returns
-------
FragilityMeasure)doc");
  py::enum_<io::FragilityAnalysis> fa(m, "FragilityAnalysis",
                                      "How observations become a fit (--analysis).");
  for (const EnumName<io::FragilityAnalysis>& row : io::kFragilityAnalysisNames)
    fa.value(row.name, row.value);
  py::class_<io::FragilityOrderNote>(m, "FragilityOrderNote",
                                     "Two damage states of a body out of order.")
      .def_readonly("body", &io::FragilityOrderNote::body)
      .def_readonly("state", &io::FragilityOrderNote::state)
      .def_readonly("medians_cross", &io::FragilityOrderNote::medians_cross)
      .def_readonly("crossing", &io::FragilityOrderNote::crossing)
      .def_readonly("latter_likelier_above", &io::FragilityOrderNote::latter_likelier_above);
  py::class_<io::FragilitySession>(m, "FragilitySession",
                                   R"doc(The fits of every damage state and body of a sweep CSV,
as ``flexrock fragility`` makes them (the same checks, observations, fits and fit CSV).)doc")
      .def(py::init([](const std::string& path, const std::string& im, bool im_given,
                       std::vector<io::DamageState> states, io::FragilityOutcome outcome,
                       double level, io::FragilityAnalysis analysis, const std::string& body,
                       double confidence, bool worst_azimuth) {
             io::FragilityOptions o;
             o.im = im;
             o.im_given = im_given;
             o.states = std::move(states);
             o.outcome = outcome;
             o.level = level;
             o.analysis = analysis;
             o.body = body;
             o.confidence = confidence;
             o.worst_azimuth = worst_azimuth;
             return std::make_unique<io::FragilitySession>(path, std::move(o));
           }),
           py::arg("path"), py::arg("im") = "pga_g", py::arg("im_given") = false,
           py::arg("states") = std::vector<io::DamageState>{},
           py::arg("outcome") = io::FragilityOutcome::kOverturned, py::arg("level") = 0.0,
           py::arg("analysis") = io::FragilityAnalysis::kRuns, py::arg("body") = "",
           py::arg("confidence") = 0.95, py::arg("worst_azimuth") = false)
      .def_property_readonly("measure", &io::FragilitySession::measure)
      .def_property_readonly("unit", &io::FragilitySession::unit)
      .def_property_readonly("states", &io::FragilitySession::states)
      .def_property_readonly("several", &io::FragilitySession::several)
      .def_property_readonly("bodies", &io::FragilitySession::bodies)
      .def("data", &io::FragilitySession::data, py::arg("state"), py::arg("body"),
           py::return_value_policy::copy)
      .def("fit", &io::FragilitySession::fit, py::arg("state"), py::arg("body"),
           py::return_value_policy::copy,
           "The fit of a state and body; raises InputError with the reason if it has none.")
      .def("fitted", &io::FragilitySession::fitted, py::arg("state"), py::arg("body"),
           "Whether a state and body could be fitted.")
      .def(
          "not_fitted",
          [](const io::FragilitySession& s) {
            std::vector<std::tuple<std::size_t, std::size_t, std::string>> out;
            for (std::size_t st = 0; st < s.states().size(); ++st) {
              for (std::size_t k = 0; k < s.bodies(); ++k) {
                if (!s.fitted(st, k)) out.emplace_back(st, k, s.not_fitted(st, k));
              }
            }
            return out;
          },
          "The states and bodies that could not be fitted: (state, body, reason) each.")
      .def(
          "stripes",
          [](const io::FragilitySession& s, std::size_t state, std::size_t body) {
            std::vector<std::tuple<double, std::size_t, std::size_t>> out;
            for (const Stripe& st : s.stripes(state, body))
              out.emplace_back(st.im, st.runs, st.failures);
            return out;
          },
          py::arg("state"), py::arg("body"),
          "The stripes of a body's observations: (IM, runs, failures) per level.")
      .def("order_notes", &io::FragilitySession::order_notes)
      .def(
          "fit_csv",
          [](const io::FragilitySession& s) {
            std::ostringstream out;
            s.write_fits(out);
            return out.str();
          },
          "The fit CSV's text, as ``flexrock fragility -o`` writes it.");
  m.def("fragility_columns", &io::fragility_columns,
        R"doc(Columns of the fit CSV of ``flexrock fragility``.

Returns
-------
list of str)doc");
  m.def("fragility_row", &io::fragility_row, py::arg("data"), py::arg("fit"),
        R"doc(One line of the fit CSV.

Parameters
----------
data : FragilityData
fit : FragilityFit

Returns
-------
str)doc");

  // qualification (docs/qualify.md): the session; flexrock.qualify() writes and renders
  py::class_<io::QualifySession>(m, "QualifySession", R"doc(A qualification from its file to
its report (flexrock qualify): the design-level runs and the IDA as journaled study sessions in
`work_dir`, resumed from there after an interruption.)doc")
      .def(py::init([](const std::string& path, const std::string& work_dir) {
             return std::make_unique<io::QualifySession>(io::load_qualify_file(path), work_dir);
           }),
           py::arg("path"), py::arg("work_dir"))
      .def_property_readonly("design_runs", &io::QualifySession::design_runs)
      .def_property_readonly("ida_sessions", &io::QualifySession::ida_sessions)
      .def_property_readonly("resumed", &io::QualifySession::resumed)
      .def(
          "run",
          [](io::QualifySession& s, int threads) {
            interruptible(threads, [&](const study::RunOptions& o) { s.run(o); });
          },
          py::arg("threads") = 0,
          R"doc(Runs what is left (the GIL is released); Ctrl-C stops it between runs and raises
KeyboardInterrupt, every finished run journaled.)doc")
      .def(
          "finish",
          [](io::QualifySession& s) {
            io::QualifyReport r;
            {
              py::gil_scoped_release nogil;
              r = s.finish();
            }
            return py::make_tuple(r.json, r.demands_csv, r.pass);
          },
          R"doc(The report: (JSON text, pelicun demand CSV text, passes).)doc");
  m.def("qualify_key_reference", &io::qualify_key_reference,
        R"doc(The key reference of qualification files (docs/qualify.md), as Markdown.)doc");
  m.def(
      "sha256_hex", [](const std::string& b) { return io::sha256_hex(b); }, py::arg("data"),
      R"doc(SHA-256 of bytes as 64 hex digits.)doc");
  m.def(
      "newmark_sliding",
      [](const std::vector<double>& t, const std::vector<double>& a, double mu_s, double mu_k,
         double g) {
        const study::NewmarkResult r = study::newmark_sliding(t, a, mu_s, mu_k, g);
        return py::dict(py::arg("max_offset_m") = r.max_offset,
                        py::arg("final_offset_m") = r.final_offset,
                        py::arg("sliding_time_s") = r.sliding_time, py::arg("slips") = r.slips);
      },
      py::arg("time"), py::arg("acceleration"), py::arg("mu_s"), py::arg("mu_k"),
      py::arg("g") = 9.80665,
      R"doc(Newmark's two-way rigid sliding block, exact for the piecewise-linear acceleration
[m/s^2] at the times [s] (two equal times make a jump); returns the peak and final offset [m],
the time sliding [s] and the slips.)doc");
}

}  // namespace flexrock::python
