// The hard contact cases of issue "Contact III" (mass ratios, heavy loads, elastic spinning
// impacts, a Newton's cradle, twist friction, tipping energy, symmetry, coming to rest), each run
// through sim::Simulation with impulse contact, rk4, dt = 1/60 s and sleeping off unless it says
// otherwise, and measured against the bound the issue sets. bench/contact_hard.cpp prints them;
// the figures of today's solver are in docs/physics-and-contact.md.
#pragma once

#include <string>
#include <vector>

namespace tumble::bench {

// One measured figure of a case against its bound.
struct HardContactFigure {
  std::string measure;  // what was measured, with its unit: "top drift (m)"
  double value = 0.0;
  double bound = 0.0;  // the bound: the case holds when value <= bound
  bool holds() const { return value <= bound; }
};

struct HardContactCase {
  std::string name;     // short, for the command line: "ratio_100"
  std::string summary;  // one line for people
  std::vector<HardContactFigure> figures;
};

// The names of every case, in a fixed order.
std::vector<std::string> hard_contact_case_names();

// Runs the case named `name` (one of hard_contact_case_names()); an unknown name gives a case
// with no figures.
HardContactCase run_hard_contact_case(const std::string& name);

}  // namespace tumble::bench
