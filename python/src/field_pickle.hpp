// SPDX-License-Identifier: BSD-3-Clause
// Pickling of the engine's read-only result structs (SimulationResult, History, Extremes, ...):
// each field is bound and listed once, and __getstate__ / __setstate__ carry a dict of every
// listed field, so that multiprocessing, joblib and dask can pass results between processes.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace flexrock::python {

template <class T>
class FieldPickle {
 public:
  explicit FieldPickle(pybind11::class_<T> c) : c_(std::move(c)) {}

  /// A read-only attribute of the member, pickled with the struct.
  template <class M, class... Extra>
  FieldPickle& def_readonly(const char* name, M T::*member, const Extra&... extra) {
    c_.def_readonly(name, member, extra...);
    return field(name, member);
  }
  /// A member pickled but bound otherwise (a property that converts it, or not at all).
  template <class M>
  FieldPickle& field(const char* name, M T::*member) {
    fields_->push_back({name, [member](const T& t) { return pybind11::cast(t.*member); },
                        [member](T& t, const pybind11::handle& v) { t.*member = v.cast<M>(); }});
    return *this;
  }
  /// A field pickled through `get(const T&)` and `set(T&, handle)` (a C array, say).
  template <class Get, class Set>
  FieldPickle& field(const char* name, Get get, Set set) {
    fields_->push_back({name, [get](const T& t) { return pybind11::cast(get(t)); },
                        [set](T& t, const pybind11::handle& v) { set(t, v); }});
    return *this;
  }
  template <class... A>
  FieldPickle& def(A&&... a) {
    c_.def(std::forward<A>(a)...);
    return *this;
  }
  template <class... A>
  FieldPickle& def_property_readonly(A&&... a) {
    c_.def_property_readonly(std::forward<A>(a)...);
    return *this;
  }
  /// Adds __getstate__ and __setstate__ over the fields listed.
  pybind11::class_<T>& pickled() {
    auto fields = fields_;
    c_.def(pybind11::pickle(
        [fields](const T& t) {
          pybind11::dict d;
          for (const Field& f : *fields) d[pybind11::str(f.name)] = f.get(t);
          return d;
        },
        [fields](const pybind11::dict& d) {
          T t{};
          for (const Field& f : *fields) {
            if (!d.contains(f.name)) {
              throw pybind11::value_error("cannot unpickle: the state lacks '" + f.name + "'");
            }
            f.set(t, d[pybind11::str(f.name)]);
          }
          return t;
        }));
    return c_;
  }

 private:
  struct Field {
    std::string name;
    std::function<pybind11::object(const T&)> get;
    std::function<void(T&, const pybind11::handle&)> set;
  };
  pybind11::class_<T> c_;
  std::shared_ptr<std::vector<Field>> fields_ = std::make_shared<std::vector<Field>>();
};

}  // namespace flexrock::python
