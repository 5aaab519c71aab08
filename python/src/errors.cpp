// The library's Error as Python exceptions: one class per Error::Kind under vorocrust.Error,
// each instance carrying the library's message and where the problem lies.
#include "bindings.hpp"

namespace vorocrust::python {
namespace {

struct ErrorClass {
  Error::Kind kind;
  const char* name;
  const char* doc;
};

constexpr ErrorClass kErrorClasses[] = {
    {Error::Kind::Usage, "UsageError", "An option or argument out of its range (the library's Error(Usage))."},
    {Error::Kind::UnreadableInput, "UnreadableInputError",
     "A missing file, an unknown format, malformed or truncated content; `file` and `line` say where."},
    {Error::Kind::InvalidGeometry, "InvalidGeometryError",
     "A readable input that is not a mesh VoroCrust accepts (NaN, no faces, self-intersections, ...)."},
    {Error::Kind::Output, "OutputError", "A result could not be written; no half-written file is left."},
    {Error::Kind::Cancelled, "Cancelled",
     "The progress callback returned False: the run stopped at its next check and wrote nothing."},
    {Error::Kind::NotImplemented, "NotYetImplementedError", "A stage this version of libvorocrust does not have yet."},
    {Error::Kind::Internal, "InternalError", "A bug: an invariant of the library did not hold."},
};

// The classes, made once at import and kept for the life of the interpreter.
PyObject* base_class = nullptr;
PyObject* kind_classes[std::size(kErrorClasses)] = {};

PyObject* class_for(Error::Kind kind) {
  for (std::size_t i = 0; i < std::size(kErrorClasses); ++i) {
    if (kErrorClasses[i].kind == kind) return kind_classes[i];
  }
  return base_class;
}

void raise(const Error& e) {
  PyObject* cls = class_for(e.kind());
  // Options named in the message spelled as Python spells them.
  const auto spelled = [&](const std::string& text) { return spelled_message(text, e.where().option, Spelling::Python); };
  py::object exception = py::reinterpret_borrow<py::object>(cls)(py::str(spelled(e.what())));
  exception.attr("kind") = to_string(e.kind());
  exception.attr("_message") = spelled(e.message());
  const Error::Location& where = e.where();
  exception.attr("file") = where.file.empty() ? py::none() : py::object(py::str(where.file));
  exception.attr("line") = where.line == 0 ? py::none() : py::object(py::int_(where.line));
  exception.attr("face") = where.face ? py::object(py::int_(*where.face)) : py::none();
  PyErr_SetObject(cls, exception.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  base_class = PyErr_NewExceptionWithDoc(
      "vorocrust.Error",
      "Every failure of libvorocrust. str(e) is the library's message with its location prefix "
      "(\"model.off:12: ...\"); the attributes say the rest:\n\n"
      "kind: the class of problem as the CLI names it (\"unreadable input\", \"cancelled\", ...)\n"
      "message: the message without the location prefix\n"
      "file: the file (or named source) concerned, or None\n"
      "line: its 1-based line, or None when unknown\n"
      "face: the face index in the merged input mesh, or None",
      PyExc_Exception, nullptr);
  if (base_class == nullptr) throw py::error_already_set();
  m.add_object("Error", py::handle(base_class));
  // Defaults for errors raised from Python (the add-ons raise UsageError themselves): the kind
  // of the class, no location, and the message as given.
  const py::handle base(base_class);
  base.attr("kind") = "error";
  base.attr("file") = py::none();
  base.attr("line") = py::none();
  base.attr("face") = py::none();
  base.attr("message") = py::module_::import("builtins").attr("property")(
      py::cpp_function([](py::handle self) -> py::object {
        const py::dict attributes = self.attr("__dict__");
        if (attributes.contains("_message")) return attributes["_message"];
        const py::tuple args = self.attr("args");
        return args.empty() ? py::str("") : py::str(args[0]);
      }),
      py::none(), py::none(), "The message without the location prefix.");
  for (std::size_t i = 0; i < std::size(kErrorClasses); ++i) {
    const std::string qualified = std::string("vorocrust.") + kErrorClasses[i].name;
    kind_classes[i] = PyErr_NewExceptionWithDoc(qualified.c_str(), kErrorClasses[i].doc, base_class, nullptr);
    if (kind_classes[i] == nullptr) throw py::error_already_set();
    py::handle(kind_classes[i]).attr("kind") = to_string(kErrorClasses[i].kind);
    m.add_object(kErrorClasses[i].name, py::handle(kind_classes[i]));
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      raise(e);
    }
  });
}

}  // namespace vorocrust::python
