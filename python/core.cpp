// vssw._core: the vssw program's commands run in this process (apps/cli.hpp), for the pure-Python package vssw/.
// One function, run(args) -> (exit code, stdout, stderr), exactly what `vssw ARGS...` would give. The GIL stays held
// for the whole run: ODE's library is not re-entrant, and nothing here calls back into Python.
#include <sstream>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "apps/cli.hpp"

namespace py = pybind11;

namespace {

// The program's text as a Python str; bytes that are not UTF-8 (a file name given on the command line, echoed in a
// message) are replaced rather than raising a UnicodeDecodeError in place of the program's own message.
py::str text(const std::string& bytes) {
    PyObject* decoded = PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()), "replace");
    if (decoded == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(decoded);
}

py::tuple run(const std::vector<std::string>& args) {
    // A C argument ends at its first NUL: "4\0junk" would be read as 4. Refused as the program refuses bad input.
    for (const std::string& arg : args)
        if (arg.find('\0') != std::string::npos)
            return py::make_tuple(vssw::cli::kExitBadInput, py::str(""),
                                  text("vssw: error: an argument holds a NUL character: '" +
                                       arg.substr(0, arg.find('\0')) + "\\0...'\n"));
    std::vector<const char*> argv;
    argv.reserve(args.size() + 2);
    argv.push_back("vssw");
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    argv.push_back(nullptr);  // argv[argc] is null, as for main()
    std::ostringstream out, err;
    const int code = vssw::cli::run(static_cast<int>(args.size() + 1), argv.data(), out, err);
    return py::make_tuple(code, text(out.str()), text(err.str()));
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "The vssw program's commands, run in-process (use the vssw package, not this module).";
    m.def("run", &run, py::arg("args"),
          "Runs `vssw ARGS...` in this process: returns (exit code, standard output, standard error). Never raises "
          "for the program's own errors: they are the exit code and the stderr line.");
    m.attr("EXIT_OK") = vssw::cli::kExitOk;
    m.attr("EXIT_OUT_OF_BOUNDS") = vssw::cli::kExitOutOfBounds;
    m.attr("EXIT_BAD_INPUT") = vssw::cli::kExitBadInput;
    m.attr("EXIT_SIMULATION_FAILED") = vssw::cli::kExitSimulationFailed;
}
