// SPDX-License-Identifier: BSD-3-Clause
// Studies (study/*.hpp, io/study_files.hpp): overturning spectra, sweeps and fragility fits.
// The GIL is released while a study runs its thread pool.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

study::RunOptions threads_only(int threads) {
  study::RunOptions o;
  o.threads = threads;
  return o;
}

}  // namespace

void bind_study(py::module_& m) {
  using namespace flexrock::study;

  py::enum_<Outcome>(m, "Outcome")
      .value("no_uplift", Outcome::kNoUplift)
      .value("rocking", Outcome::kRocking)
      .value("overturned_after_impacts", Outcome::kOverturnedAfterImpacts)
      .value("overturned_without_impact", Outcome::kOverturnedWithoutImpact)
      .value("contact_lost", Outcome::kContactLost)
      .value("stopped", Outcome::kStopped);
  m.def("overturned", &overturned, py::arg("outcome"), "True for both overturning classes.");

  py::class_<RunSummary>(m, "RunSummary", "What a study keeps of one simulation.")
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
      .def_readonly("t_end", &RunSummary::t_end);
  m.def("summarize", &summarize, py::arg("body"), py::arg("result"),
        "The study outcome class of a finished simulation.");

  // spectra
  py::enum_<PulseType>(m, "PulseType")
      .value("one_sine", PulseType::kOneSine)
      .value("half_sine", PulseType::kHalfSine)
      .value("cycloidal_a", PulseType::kCycloidalA)
      .value("cycloidal_b", PulseType::kCycloidalB)
      .value("cycloidal_c", PulseType::kCycloidalC)
      .value("ricker", PulseType::kRicker);
  m.def("pulse_type_from_string", &pulse_type_from_string, py::arg("name"));

  py::class_<SpectrumSpec>(m, "SpectrumSpec", "A pulse spectrum: pulse x amplitude x frequency.")
      .def(py::init<>())
      .def_readwrite("pulse", &SpectrumSpec::pulse)
      .def_readwrite("normalized", &SpectrumSpec::normalized)
      .def_readwrite("amplitudes", &SpectrumSpec::amplitudes)
      .def_readwrite("frequencies", &SpectrumSpec::frequencies)
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
  py::class_<SpectrumResult>(m, "SpectrumResult")
      .def_readonly("alpha", &SpectrumResult::alpha)
      .def_readonly("tan_alpha", &SpectrumResult::tan_alpha)
      .def_readonly("p", &SpectrumResult::p)
      .def_readonly("cells", &SpectrumResult::cells)
      .def_readonly("boundary", &SpectrumResult::boundary);
  m.def(
      "compute_spectrum",
      [](const Body& body, const SpectrumSpec& spec, int threads) {
        return compute_spectrum(body, spec, threads_only(threads));
      },
      py::arg("body"), py::arg("spec"), py::arg("threads") = 0,
      py::call_guard<py::gil_scoped_release>(),
      "Every cell of a pulse spectrum, then the minimum overturning amplitude of each column.");
  m.def(
      "compute_record_spectrum",
      [](const Body& body, const RecordSpectrumSpec& spec, int threads) {
        return compute_record_spectrum(body, spec, threads_only(threads));
      },
      py::arg("body"), py::arg("spec"), py::arg("threads") = 0,
      py::call_guard<py::gil_scoped_release>(), "One record x scale factors.");
  m.def("run_pulse_cell", &run_pulse_cell, py::arg("body"), py::arg("spec"), py::arg("a_p"),
        py::arg("omega_p"), py::call_guard<py::gil_scoped_release>(),
        "One pulse-spectrum cell (a_p [m/s^2], omega_p [rad/s]) as compute_spectrum runs it.");
  m.def("run_record_cell", &run_record_cell, py::arg("body"), py::arg("spec"), py::arg("scale"),
        py::call_guard<py::gil_scoped_release>(), "One record-spectrum cell.");
  m.def("pulse_motion", &pulse_motion, py::arg("type"), py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"));
  m.def("pulse_length", &pulse_length, py::arg("type"), py::arg("omega_p"));

  // sweeps
  py::class_<Intensity>(m, "Intensity")
      .def_readonly("pga", &Intensity::pga, "[m/s^2]")
      .def_readonly("pgv", &Intensity::pgv, "[m/s]");
  m.def("intensity", &intensity, py::arg("motion"), py::arg("analytic_dt") = 1e-3);
  py::class_<SweepBody>(m, "SweepBody")
      .def(py::init([](std::string name, BodyParameters body) {
             return SweepBody{std::move(name), std::move(body)};
           }),
           py::arg("name"), py::arg("body"))
      .def_readwrite("name", &SweepBody::name)
      .def_readwrite("body", &SweepBody::body);
  py::class_<SweepRecord>(m, "SweepRecord")
      .def(py::init([](std::string name, GroundMotion motion) {
             return SweepRecord{std::move(name), std::move(motion)};
           }),
           py::arg("name"), py::arg("motion"))
      .def_readwrite("name", &SweepRecord::name)
      .def_readwrite("motion", &SweepRecord::motion);
  py::enum_<ScaleKind>(m, "ScaleKind")
      .value("factor", ScaleKind::kFactor)
      .value("target_pga", ScaleKind::kTargetPga);
  py::class_<SweepSpec>(m, "SweepSpec", "Bodies x records x scale factors.")
      .def(py::init<>())
      .def_readwrite("bodies", &SweepSpec::bodies)
      .def_readwrite("records", &SweepSpec::records)
      .def_readwrite("scale_kind", &SweepSpec::scale_kind)
      .def_readwrite("scales", &SweepSpec::scales)
      .def_readwrite("free_periods", &SweepSpec::free_periods)
      .def_readwrite("solver", &SweepSpec::solver);
  py::class_<SweepRow>(m, "SweepRow")
      .def_readonly("index", &SweepRow::index)
      .def_readonly("body", &SweepRow::body)
      .def_readonly("record", &SweepRow::record)
      .def_readonly("scale_index", &SweepRow::scale_index)
      .def_readonly("scale", &SweepRow::scale)
      .def_readonly("pga", &SweepRow::pga)
      .def_readonly("pgv", &SweepRow::pgv)
      .def_readonly("duration", &SweepRow::duration)
      .def_readonly("message", &SweepRow::message)
      .def_readonly("run", &SweepRow::run);
  m.def(
      "run_sweep",
      [](const SweepSpec& spec, const std::vector<std::size_t>& indices, int threads) {
        return run_sweep(spec, indices, threads_only(threads));
      },
      py::arg("spec"), py::arg("indices") = std::vector<std::size_t>{}, py::arg("threads") = 0,
      py::call_guard<py::gil_scoped_release>(),
      "Runs the sweep (or the given run indices); rows in index order.");

  // fragility
  py::class_<FragilityFit>(m, "FragilityFit", "Lognormal fragility P = Phi(ln(x/theta)/beta).")
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
      .def_readonly("log_likelihood", &FragilityFit::log_likelihood)
      .def_readonly("iterations", &FragilityFit::iterations)
      .def_readonly("samples", &FragilityFit::samples)
      .def_readonly("failures", &FragilityFit::failures);
  m.def("fit_lognormal", &fit_lognormal, py::arg("im"), py::arg("failed"),
        py::arg("confidence") = 0.95, "Maximum-likelihood lognormal fragility.");
  m.def("fragility_probability", &fragility_probability, py::arg("fit"), py::arg("x"));
  m.def(
      "fragility_band",
      [](const FragilityFit& fit, double x) {
        double lo = 0.0, hi = 0.0;
        fragility_band(fit, x, lo, hi);
        return py::make_tuple(lo, hi);
      },
      py::arg("fit"), py::arg("x"), "(lower, upper) pointwise confidence band at x.");
  m.def("lognormal_log_likelihood", &lognormal_log_likelihood, py::arg("im"), py::arg("failed"),
        py::arg("theta"), py::arg("beta"));

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
  m.def("load_spectrum_file", &io::load_spectrum_file, py::arg("path"));
  m.def("spectrum_columns", &io::spectrum_columns);
  m.def("boundary_columns", &io::boundary_columns);
  m.def(
      "spectrum_csv",
      [](const SpectrumResult& r, double g) {
        std::ostringstream out;
        io::write_spectrum_csv(out, r, g);
        return out.str();
      },
      py::arg("result"), py::arg("g"), "The spectrum CSV text (one row per cell).");
  m.def(
      "boundary_csv",
      [](const SpectrumResult& r, bool normalized, double g) {
        std::ostringstream out;
        io::write_boundary_csv(out, r, normalized, g);
        return out.str();
      },
      py::arg("result"), py::arg("normalized"), py::arg("g"),
      "The minimum-overturning CSV text (one row per frequency column).");

  py::class_<io::SweepManifest>(m, "SweepManifest")
      .def_readonly("source", &io::SweepManifest::source)
      .def_readonly("spec", &io::SweepManifest::spec)
      .def_readonly("hash", &io::SweepManifest::hash);
  m.def("load_sweep_manifest", &io::load_sweep_manifest, py::arg("path"));
  m.def("sweep_columns", &io::sweep_columns);
  m.def("sweep_row", &io::sweep_row, py::arg("spec"), py::arg("row"),
        "One line of the sweep CSV (no line end).");

  py::class_<io::CsvTable>(m, "CsvTable")
      .def_readonly("source", &io::CsvTable::source)
      .def_readonly("columns", &io::CsvTable::columns)
      .def_readonly("rows", &io::CsvTable::rows);
  m.def("read_csv_table", &io::read_csv_table, py::arg("path"));
  py::class_<io::FragilityQuery>(m, "FragilityQuery")
      .def(py::init<>())
      .def_readwrite("im", &io::FragilityQuery::im)
      .def_readwrite("outcome", &io::FragilityQuery::outcome)
      .def_readwrite("level", &io::FragilityQuery::level)
      .def_readwrite("body", &io::FragilityQuery::body);
  py::class_<io::FragilityData>(m, "FragilityData")
      .def_readonly("body", &io::FragilityData::body)
      .def_readonly("im", &io::FragilityData::im)
      .def_readonly("failed", &io::FragilityData::failed)
      .def_readonly("excluded", &io::FragilityData::excluded);
  m.def("fragility_data", &io::fragility_data, py::arg("table"), py::arg("query"));
  m.def("fragility_columns", &io::fragility_columns);
  m.def("fragility_row", &io::fragility_row, py::arg("data"), py::arg("fit"));
}

}  // namespace flexrock::python
