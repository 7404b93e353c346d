// SPDX-License-Identifier: BSD-3-Clause
// Files (io/records.hpp, io/case_file.hpp, io/outputs.hpp): records, case files and the outputs
// the command line writes, byte for byte the same.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>

#include "bindings.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/records.hpp"

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
      .def_readonly("time", &io::Record::time, "[s]")
      .def_readonly("values", &io::Record::values, "in `units`")
      .def_property_readonly("npts", &io::Record::npts)
      .def_property_readonly("duration", &io::Record::duration)
      .def("to_si", &io::Record::to_si, py::arg("scale") = 1.0)
      .def("to_motion", &io::Record::to_motion, py::arg("scale") = 1.0,
           "The record as a horizontal ground motion [m/s^2] times `scale`.");
  m.def("read_at2", &io::read_at2, py::arg("path"), "Reads a PEER NGA .AT2 file.");
  m.def("read_single_column", &io::read_single_column, py::arg("path"), py::arg("dt"),
        py::arg("units"), "Reads values sampled every dt [s].");
  m.def("read_time_series", &io::read_time_series, py::arg("path"), py::arg("units"),
        "Reads time/acceleration pairs.");
  m.def(
      "combine",
      [](const io::Record& h, const io::Record* v, double scale) {
        return io::combine(h, v, scale);
      },
      py::arg("horizontal"), py::arg("vertical") = nullptr, py::arg("scale") = 1.0,
      "A horizontal record with an optional vertical one, as a ground motion [m/s^2].");

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
      .def_readwrite("motion", &io::Case::motion)
      .def_readwrite("horizontal", &io::Case::horizontal)
      .def_readwrite("vertical", &io::Case::vertical)
      .def_readwrite("excitation_scale", &io::Case::excitation_scale)
      .def_readwrite("initial", &io::Case::initial)
      .def_readwrite("options", &io::Case::options)
      .def_readwrite("output", &io::Case::output);
  m.def("load_case", &io::load_case, py::arg("path"), "Reads and checks a case file (TOML).");
  m.def(
      "load_body",
      [](const std::string& path) {
        std::string type;
        BodyParameters p = io::load_body(path, &type);
        return py::make_tuple(std::move(p), type);
      },
      py::arg("path"), "The [body] table of a case or body file: (BodyParameters, type).");

  py::class_<io::OutputPaths>(m, "OutputPaths")
      .def(py::init<>())
      .def_readwrite("time_history", &io::OutputPaths::time_history)
      .def_readwrite("summary", &io::OutputPaths::summary)
      .def_readwrite("events", &io::OutputPaths::events);

  m.def("time_history_columns", &io::time_history_columns, py::arg("modes"));
  m.def("event_columns", &io::event_columns);
  m.def(
      "time_history_csv",
      [](const SimulationResult& r, const Body& body) {
        std::ostringstream out;
        io::write_time_history(out, r, body);
        return out.str();
      },
      py::arg("result"), py::arg("body"), "The time-history CSV text the command line writes.");
  m.def(
      "events_csv",
      [](const SimulationResult& r) {
        std::ostringstream out;
        io::write_events(out, r);
        return out.str();
      },
      py::arg("result"), "The event-log CSV text the command line writes.");
  m.def("summary_json", &io::summary_json, py::arg("case"), py::arg("body"), py::arg("result"),
        py::arg("paths") = io::OutputPaths{}, "The summary JSON text the command line writes.");
  m.def("write_outputs", &io::write_outputs, py::arg("case"), py::arg("body"), py::arg("result"),
        py::arg("output_dir") = std::string(),
        "Writes the outputs the case asks for, as the command line does; returns the paths.");
}

}  // namespace flexrock::python
