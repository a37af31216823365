// The method the command line chose: a row of the method registry by its name, or else a diagonally implicit tableau
// read from a file, and the stepper that runs it.
#include "studies.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"

#include <sys/stat.h>

using namespace cloth;

namespace ch09 {

MethodChoice choose(const std::string& argument) {
  MethodChoice choice;
  choice.argument = argument;
  std::string names;
  for (const Method* m : newton_methods()) {
    if (m->name == argument) choice.row = m;
    names += (names.empty() ? "" : ", ") + m->name;
  }
  if (choice.row != nullptr) {
    if (!choice.multistep()) choice.tableau = builtin_implicit_tableau(argument);
    return choice;
  }
  struct stat info {};
  if (::stat(argument.c_str(), &info) != 0)
    throw InputError("--tableau: '" + escaped(argument) + "' is neither a registered implicit method (" + names +
                     ") nor a readable tableau file");
  try {
    choice.tableau = read_implicit_tableau(argument);
  } catch (const InputError& e) {
    throw InputError(std::string("--tableau: ") + e.what());
  }
  return choice;
}

std::unique_ptr<NewtonStepper> make_method(const MethodChoice& choice, ForceField& field) {
  if (choice.row != nullptr) return make_newton_stepper(choice.row->name, field, {choice.newton});
  return std::make_unique<DiagonallyImplicitRungeKutta>(field, choice.tableau, choice.newton);
}

std::vector<MethodChoice> study_methods(const NewtonSettings& newton) {
  std::vector<MethodChoice> methods;
  for (const Method* m : newton_methods()) {
    MethodChoice choice = choose(m->name);
    choice.newton = newton;
    methods.push_back(choice);
  }
  return methods;
}

}  // namespace ch09
