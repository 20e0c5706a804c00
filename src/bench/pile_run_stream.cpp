#include "bench/pile_run_stream.hpp"

#include <charconv>
#include <cstddef>
#include <optional>
#include <vector>

namespace tumble::bench {
namespace {

constexpr std::string_view kHeader = "tumble-pile-run 1";

// The words of `text` between single spaces.
std::vector<std::string_view> words_of(std::string_view text) {
  std::vector<std::string_view> words;
  while (!text.empty()) {
    const std::size_t space = text.find(' ');
    words.push_back(text.substr(0, space));
    if (space == std::string_view::npos) break;
    text.remove_prefix(space + 1);
  }
  return words;
}

// A number that is the whole of `word`; nothing when it is not one.
template <typename Number>
std::optional<Number> number_in(std::string_view word) {
  Number value{};
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

// "step" and " 1.5 2" from "step 1.5 2": the line's keyword and the rest after the space.
std::pair<std::string_view, std::string_view> split_keyword(std::string_view line) {
  const std::size_t space = line.find(' ');
  if (space == std::string_view::npos) return {line, {}};
  return {line.substr(0, space), line.substr(space + 1)};
}

}  // namespace

bool write_run_start(std::FILE* out, const std::string& engine, const Pile& pile) {
  std::fprintf(out, "%.*s\nengine %s\npile %s\n", static_cast<int>(kHeader.size()), kHeader.data(),
               engine.c_str(), pile.summary.c_str());
  return std::fflush(out) == 0;
}

bool write_run_step(std::FILE* out, const PileRun& so_far) {
  std::fprintf(out, "step %.17g %.17g %d %.17g %.17g\n", so_far.step_ms.back(),
               so_far.step_cpu_ms.back(), so_far.contacts.back(), so_far.depth_m.back(),
               so_far.top_speed.back());
  return std::fflush(out) == 0;  // each step as it is done, for the reader's progress
}

bool write_run_end(std::FILE* out, const PileRun& run) {
  std::fprintf(out, "escaped %d\nlargest_penetration_m %.17g\nlargest_final_speed %.17g\n",
               run.escaped, run.largest_penetration_m, run.largest_final_speed);
  for (const physics::Vec3& p : run.final_positions) {
    std::fprintf(out, "position %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  }
  std::fputs("end\n", out);
  return std::fflush(out) == 0 && !std::ferror(out);
}

bool PileRunReader::fail(const std::string& why) {
  if (error_.empty()) error_ = "line " + std::to_string(line_number_) + ": " + why;
  part_ = Part::done;
  return false;
}

bool PileRunReader::read_step(std::string_view values) {
  const std::vector<std::string_view> words = words_of(values);
  if (words.size() != 5) return fail("a step needs 5 numbers, got " + std::to_string(words.size()));
  const auto ms = number_in<double>(words[0]);
  const auto cpu_ms = number_in<double>(words[1]);
  const auto contacts = number_in<int>(words[2]);
  const auto depth = number_in<double>(words[3]);
  const auto top_speed = number_in<double>(words[4]);
  if (!ms || !cpu_ms || !contacts || !depth || !top_speed) {
    return fail("not a step's numbers: " + std::string(values));
  }
  if (run_.step_ms.size() == static_cast<std::size_t>(pile_.steps)) {
    return fail("more steps than the pile's " + std::to_string(pile_.steps));
  }
  run_.step_ms.push_back(*ms);
  run_.step_cpu_ms.push_back(*cpu_ms);
  run_.contacts.push_back(*contacts);
  run_.depth_m.push_back(*depth);
  run_.top_speed.push_back(*top_speed);
  return true;
}

bool PileRunReader::read_position(std::string_view values) {
  const std::vector<std::string_view> words = words_of(values);
  std::optional<double> xyz[3];
  for (std::size_t k = 0; k < 3 && k < words.size(); ++k) xyz[k] = number_in<double>(words[k]);
  if (words.size() != 3 || !xyz[0] || !xyz[1] || !xyz[2]) {
    return fail("not a position's three numbers: " + std::string(values));
  }
  if (run_.final_positions.size() == pile_.boxes.size()) {
    return fail("more positions than the pile's " + std::to_string(pile_.boxes.size()) + " boxes");
  }
  run_.final_positions.emplace_back(*xyz[0], *xyz[1], *xyz[2]);
  return true;
}

Result<void> PileRunReader::read(std::string_view line) {
  if (take(line)) return {};
  return Error{error_};
}

bool PileRunReader::take(std::string_view line) {
  if (!error_.empty()) return false;
  ++line_number_;
  const auto [keyword, rest] = split_keyword(line);
  switch (part_) {
    case Part::header:
      if (line != kHeader)
        return fail("expected \"tumble-pile-run 1\", got \"" + std::string(line) + "\"");
      part_ = Part::engine;
      return true;
    case Part::engine:
      if (keyword != "engine" || rest.empty()) return fail("expected the engine's name");
      run_.engine = std::string(rest);
      part_ = Part::pile;
      return true;
    case Part::pile:
      if (keyword != "pile") return fail("expected the pile's summary");
      if (rest != pile_.summary) {
        return fail("the peer ran another pile: \"" + std::string(rest) + "\", not \"" +
                    pile_.summary + "\"");
      }
      part_ = Part::steps;
      return true;
    case Part::steps:
      if (keyword == "step") return read_step(rest);
      if (run_.step_ms.size() != static_cast<std::size_t>(pile_.steps)) {
        return fail(std::to_string(run_.step_ms.size()) + " steps, not the pile's " +
                    std::to_string(pile_.steps));
      }
      part_ = Part::escaped;
      [[fallthrough]];
    case Part::escaped: {
      const auto escaped = number_in<int>(rest);
      if (keyword != "escaped" || !escaped) return fail("expected \"escaped <count>\"");
      run_.escaped = *escaped;
      part_ = Part::penetration;
      return true;
    }
    case Part::penetration: {
      const auto depth = number_in<double>(rest);
      if (keyword != "largest_penetration_m" || !depth) {
        return fail("expected \"largest_penetration_m <m>\"");
      }
      run_.largest_penetration_m = *depth;
      part_ = Part::final_speed;
      return true;
    }
    case Part::final_speed: {
      const auto speed = number_in<double>(rest);
      if (keyword != "largest_final_speed" || !speed) {
        return fail("expected \"largest_final_speed <m/s>\"");
      }
      run_.largest_final_speed = *speed;
      part_ = Part::positions;
      return true;
    }
    case Part::positions:
      if (keyword == "position") return read_position(rest);
      if (line != "end") return fail("expected a position or \"end\"");
      if (run_.final_positions.size() != pile_.boxes.size()) {
        return fail(std::to_string(run_.final_positions.size()) +
                    " positions, not one for each of the pile's " +
                    std::to_string(pile_.boxes.size()) + " boxes");
      }
      part_ = Part::done;
      return true;
    case Part::done:
      return fail("more after \"end\"");
  }
  return false;  // every part returns above; the compiler cannot know that `part_` is one
}

}  // namespace tumble::bench
