// onetip.Error (a RuntimeError) and one subclass per onetip::ErrorKind:
// InputError (bad files, sources, option values), StateError (a call that is
// not valid now) and InternalError (a bug). Every onetip::Error thrown by the
// C++ API reaches Python as the subclass of its kind, with its message.
#include <Python.h>

#include "bindings.hpp"
#include "onetip/error.hpp"

namespace py = pybind11;

namespace onetip::python {
namespace {

// Module-lifetime exception types: each holds one reference that is never
// released (the interpreter may already be gone when static destructors run).
struct ErrorTypes {
  PyObject* base = nullptr;
  PyObject* input = nullptr;
  PyObject* state = nullptr;
  PyObject* internal = nullptr;
};
ErrorTypes types;

PyObject* newType(py::module_& m, const char* name, PyObject* base, const char* doc) {
  const std::string qualified = std::string("onetip.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw py::error_already_set();
  m.attr(name) = py::handle(type);
  return type;
}

PyObject* typeOf(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::input: return types.input;
    case ErrorKind::state: return types.state;
    case ErrorKind::internal: break;
  }
  return types.internal;
}

}  // namespace

void bindErrors(py::module_& m) {
  types.base = newType(m, "Error", PyExc_RuntimeError, "Any failure reported by onetip; str(e) says what is wrong.");
  types.input = newType(m, "InputError", types.base,
                        "Bad input: a missing or malformed file, a bad source or an invalid option value.");
  types.state = newType(m, "StateError", types.base, "The call is not valid now (e.g. start() twice).");
  types.internal = newType(m, "InternalError", types.base, "An unexpected failure inside onetip (a bug).");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(typeOf(e.kind()), e.what());
    }
  });
}

}  // namespace onetip::python
