// tumble._tumble: the C++ half of the Python module `tumble` (python/tumble/__init__.py is the
// other). It loads scenes, runs their physics into arrays and renders them through the same
// functions as the command line (job::prepare_render and job::render_to_folder, job::state_row),
// so that the numbers and the files are the CLI's bit for bit. Long work runs with the GIL
// released; Ctrl-C is looked for every 50 ms and stops the work as it stops the CLI.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "job/render_folder.hpp"
#include "job/state_rows.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"

namespace py = pybind11;

namespace tumble::python {
namespace {

using Clock = std::chrono::steady_clock;

// A scene file's error ("FILE:LINE:COL: KEY: message"), raised as tumble.SceneError (defined in
// python/tumble/_errors.py, which reads the file, line, column and key back out of the message).
struct SceneError {
  std::string message;
};

// The scene and the text it was read from (the scene's hash, and the render, need the text).
struct LoadedScene {
  scene::Scene scene;
  std::string text;
  std::string path;
};

LoadedScene parse(std::string text, const std::string& path) {
  Result<scene::Scene> parsed = scene::parse_scene(text, path);
  if (!parsed) throw SceneError{parsed.error()};
  return LoadedScene{std::move(parsed).value(), std::move(text), path};
}

LoadedScene load(const std::string& path) {
  Result<std::string> text = scene::read_scene_text(path);
  if (!text) throw SceneError{text.error()};
  return parse(std::move(text).value(), path);
}

// Asked while the GIL is released: whether a signal's Python handler raised (Ctrl-C's
// KeyboardInterrupt). Takes the GIL at most every 50 ms, so that the work it watches is not
// slowed by waiting for it; the exception is kept to be raised when the work has stopped.
class InterruptWatch {
 public:
  bool operator()() {
    if (raised_) return true;
    const Clock::time_point now = Clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return false;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) raised_.emplace();  // fetches the exception the handler raised
    return raised_.has_value();
  }
  // Raises the handler's exception, if one was raised (with the GIL held).
  void raise_if_raised() {
    if (raised_) throw std::move(*raised_);
  }

 private:
  Clock::time_point last_ = Clock::now();
  std::optional<py::error_already_set> raised_;
};

py::array_t<double> array_of(const std::vector<double>& values, std::size_t rows,
                             std::size_t columns) {
  py::array_t<double> out = columns == 1 ? py::array_t<double>(static_cast<py::ssize_t>(rows))
                                         : py::array_t<double>({static_cast<py::ssize_t>(rows),
                                                                static_cast<py::ssize_t>(columns)});
  if (!values.empty())
    std::memcpy(out.mutable_data(), values.data(), values.size() * sizeof(double));
  return out;
}

// {"t": (n,), "bodies": [name, ...], "states": [{column: array}, ...]}: the rows of `tumble
// simulate --every every`, each body's columns as arrays (position (n, 3), orientation (n, 4) as
// w, x, y, z, ...). Errors: a blow-up raises tumble.SimulationError (RuntimeError).
py::dict simulate(const LoadedScene& loaded, std::int64_t every) {
  if (every < 1)
    throw py::value_error("every: expected a whole number >= 1, got " + std::to_string(every));
  const scene::Scene& scene = loaded.scene;
  const std::size_t bodies = scene.bodies.size();
  std::vector<double> times;
  std::vector<std::vector<double>> rows(bodies);  // per body, the 20 columns of each sample
  std::optional<std::string> failure;
  InterruptWatch interrupted;
  {
    py::gil_scoped_release released;
    sim::Simulation simulation = scene::build_simulation(scene);
    const std::int64_t steps = scene::step_count(scene);
    const auto sample = [&] {
      times.push_back(simulation.time());
      for (std::size_t i = 0; i < bodies; ++i) {
        const io::StateRow row = job::state_row(simulation.current()[i]);
        rows[i].insert(rows[i].end(), row.begin(), row.end());
      }
    };
    sample();
    for (std::int64_t n = 1; n <= steps; ++n) {
      simulation.step();
      if (interrupted()) break;
      if (const auto& blow_up = simulation.blow_up()) {
        failure = scene::blow_up_message(scene, *blow_up);
        break;
      }
      if (job::sampled_step(n, every, steps)) sample();
    }
  }
  interrupted.raise_if_raised();
  if (failure) {
    py::object error = py::module_::import("tumble._errors").attr("SimulationError");
    PyErr_SetString(error.ptr(), failure->c_str());
    throw py::error_already_set();
  }
  const std::size_t n = times.size();
  py::list names;
  py::list states;
  // (first column, how many) of each array, in io::kStateColumns.
  struct Field {
    const char* name;
    std::size_t first, count;
  };
  constexpr Field kFields[] = {{"position", 0, 3},    {"velocity", 3, 3},
                               {"orientation", 6, 4}, {"angular_velocity", 10, 3},
                               {"momentum", 13, 3},   {"angular_momentum", 16, 3},
                               {"energy", 19, 1}};
  constexpr std::size_t kColumns = io::kStateColumns.size();
  for (std::size_t i = 0; i < bodies; ++i) {
    names.append(scene.bodies[i].name);
    py::dict state;
    for (const Field& field : kFields) {
      std::vector<double> values;
      values.reserve(n * field.count);
      for (std::size_t r = 0; r < n; ++r) {
        const double* row = rows[i].data() + r * kColumns + field.first;
        values.insert(values.end(), row, row + field.count);
      }
      state[field.name] = array_of(values, n, field.count);
    }
    states.append(state);
  }
  py::dict out;
  out["t"] = array_of(times, n, 1);
  out["bodies"] = names;
  out["states"] = states;
  return out;
}

// Renders as `tumble render` with these overrides; returns {"directory", "written", "kept",
// "warnings"}. Raises SceneError for a scene or override the render refuses, RenderError
// (RuntimeError) for a render that failed, KeyboardInterrupt when Ctrl-C stopped it (the folder
// left as it was, as the CLI leaves it).
py::dict render(const LoadedScene& loaded, const std::string& output,
                const std::optional<std::vector<std::string>>& formats, std::optional<int> width,
                std::optional<int> height, std::optional<int> fps,
                const std::optional<std::string>& quality, std::optional<bool> frames,
                const std::string& shader_directory, const std::string& web_directory) {
  job::RenderOptions options;
  options.scene_path = loaded.path;
  options.output_root = output;
  if (formats) {
    if (formats->empty()) throw py::value_error("formats: list one or more formats");
    options.formats = *formats;
  }
  options.width = width;
  options.height = height;
  options.fps = fps;
  options.quality = quality;
  if (frames) options.frames = *frames;
  options.quiet = true;
  options.shader_directory = shader_directory;
  options.web_directory = web_directory;
  Result<job::PreparedRender> prepared = job::prepare_render(loaded.text, options, Clock::now());
  if (!prepared) throw SceneError{prepared.error()};
  job::RenderOutcome outcome;
  InterruptWatch interrupted;
  Result<void> rendered = Result<void>::success();
  {
    py::gil_scoped_release released;
    rendered = job::render_to_folder(
        *prepared, std::ref(interrupted), [](std::int64_t) {}, outcome);
  }
  interrupted.raise_if_raised();
  if (!rendered) {
    py::object error = py::module_::import("tumble._errors").attr("RenderError");
    PyErr_SetString(error.ptr(), rendered.error().c_str());
    throw py::error_already_set();
  }
  py::list kept;
  for (const job::RenderedFile& file : outcome.kept) kept.append(file.name);
  std::vector<std::string> warnings = scene::stability_warnings(prepared->job.scene);
  warnings.insert(warnings.end(), outcome.result.warnings.begin(), outcome.result.warnings.end());
  if (!outcome.leftover.empty()) warnings.push_back(outcome.leftover);
  py::dict out;
  out["directory"] = prepared->job.directory.string();
  out["written"] = outcome.written;
  out["kept"] = kept;
  out["warnings"] = warnings;
  return out;
}

}  // namespace
}  // namespace tumble::python

PYBIND11_MODULE(_tumble, m) {
  using namespace tumble::python;
  m.doc() = "tumble's C++ core: scenes, their physics and their renders";
  m.attr("__version__") = TUMBLE_VERSION;
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const SceneError& error) {
      py::object type = py::module_::import("tumble._errors").attr("SceneError");
      PyErr_SetObject(type.ptr(), py::str(error.message).ptr());
    }
  });
  py::class_<LoadedScene>(m, "_Scene")
      .def_property_readonly("name", [](const LoadedScene& s) { return s.scene.name; })
      .def_property_readonly("path", [](const LoadedScene& s) { return s.path; })
      .def_property_readonly("text", [](const LoadedScene& s) { return s.text; })
      .def_property_readonly("duration", [](const LoadedScene& s) { return s.scene.duration; })
      .def_property_readonly("fps", [](const LoadedScene& s) { return s.scene.fps; })
      .def_property_readonly("dt", [](const LoadedScene& s) { return s.scene.physics.dt; })
      .def_property_readonly("width", [](const LoadedScene& s) { return s.scene.render.width; })
      .def_property_readonly("height", [](const LoadedScene& s) { return s.scene.render.height; })
      .def_property_readonly("bodies",
                             [](const LoadedScene& s) {
                               std::vector<std::string> names;
                               for (const auto& body : s.scene.bodies) names.push_back(body.name);
                               return names;
                             })
      .def_property_readonly(
          "steps", [](const LoadedScene& s) { return tumble::scene::step_count(s.scene); })
      .def("check", [](const LoadedScene& s) { return tumble::scene::stability_warnings(s.scene); })
      .def("simulate", &simulate, py::arg("every") = 1)
      .def("render", &render, py::arg("output"), py::arg("formats"), py::arg("width"),
           py::arg("height"), py::arg("fps"), py::arg("quality"), py::arg("frames"),
           py::arg("shader_directory"), py::arg("web_directory"));
  m.def("load", &load, py::arg("path"));
  m.def("loads", &parse, py::arg("text"), py::arg("path"));
}
