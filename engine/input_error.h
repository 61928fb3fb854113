#pragma once
// The error a user can cause (a bad file, a broken surface, a bad option).
// Its message is one line naming the input and the fault, ready to print.
// What the user can change about it comes as a hint beside the message: the
// layers below the app know the fact, not the command line's flags or the
// scenario's keys, so the app words the advice.

#include <stdexcept>
#include <string>
#include <string_view>

namespace mtcut::engine {

// A setting of the input the user can change to get past a fault or a doubt.
struct InputHint {
  enum class Kind {
    kNone,
    kUnits,      // the mesh file's length unit: to state it
    kMaxVolume,  // the largest tet volume TetGen meshes to: to raise it
  };
  Kind kind = Kind::kNone;
  // kUnits: the symbol of the unit that fits ("mm"), static text so that a
  // hint copies without allocating, as an exception must; empty when none does.
  std::string_view unit;
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, InputHint hint = {}) : std::runtime_error(message), hint_(hint) {}
  const InputHint& hint() const { return hint_; }

 private:
  InputHint hint_;
};

// A line for the user about an input that loaded (a repair, a size that
// looks like other units), with its hint.
struct InputNote {
  std::string text;
  InputHint hint = {};
};

// Builds "source: line N: what" (line omitted when 0).
std::string describe_at(const std::string& source, std::size_t line, const std::string& what);

}  // namespace mtcut::engine
