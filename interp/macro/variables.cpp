#include "interp/macro/variables.hpp"

#include <fmt/format.h>

namespace lathesim::interp::macro {

VariableStore::VariableStore(const std::map<int, double>& commonValues) : locals_(1) {
  for (const auto& [number, value] : commonValues) {
    if (number >= 100 && number <= 199) common100_[static_cast<std::size_t>(number - 100)] = value;
    if (number >= 500 && number <= 999) common500_[static_cast<std::size_t>(number - 500)] = value;
  }
}

bool VariableStore::isCommon(int number) {
  return (number >= 100 && number <= 199) || (number >= 500 && number <= 999);
}

Status VariableStore::noSuchVariable(int number, int line, int column) const {
  if (number >= 1000) {
    return Error{line, column,
                 fmt::format("#{} is a system variable of the control; lathesim simulates only #3000 (alarm) "
                             "and #3006 (stop with a message), written by the program",
                             number)};
  }
  return Error{line, column,
               fmt::format("#{} is not a variable: a Fanuc control has #0 (always vacant), local #1–#33 and "
                           "common #100–#199 and #500–#999",
                           number)};
}

Result<Value> VariableStore::read(int number, int line, int column) const {
  if (number == 0) return Value{};
  if (number >= 1 && number <= kLocalCount) return locals_.back()[static_cast<std::size_t>(number - 1)];
  if (number >= 100 && number <= 199) return common100_[static_cast<std::size_t>(number - 100)];
  if (number >= 500 && number <= 999) return common500_[static_cast<std::size_t>(number - 500)];
  return noSuchVariable(number, line, column).error();
}

Status VariableStore::write(int number, Value value, int line, int column) {
  if (number == 0) {
    return Error{line, column, "#0 is always vacant and cannot be set; to empty a variable, write #i = #0"};
  }
  if (number >= 1 && number <= kLocalCount) {
    locals_.back()[static_cast<std::size_t>(number - 1)] = value;
  } else if (number >= 100 && number <= 199) {
    common100_[static_cast<std::size_t>(number - 100)] = value;
  } else if (number >= 500 && number <= 999) {
    common500_[static_cast<std::size_t>(number - 500)] = value;
  } else {
    return noSuchVariable(number, line, column);
  }
  return success();
}

}  // namespace lathesim::interp::macro
