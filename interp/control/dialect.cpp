#include "interp/control/dialect.hpp"

namespace lathesim::interp {

std::optional<Dialect> dialectNamed(std::string_view name) {
  for (Dialect dialect : kDialects)
    if (name == dialectName(dialect)) return dialect;
  return std::nullopt;
}

std::string_view dialectName(Dialect dialect) {
  switch (dialect) {
    case Dialect::FanucA: return "fanuc-a";
    case Dialect::FanucB: return "fanuc-b";
    case Dialect::Hnc: return "hnc";
    case Dialect::Haas: return "haas";
  }
  return "unknown";
}

}  // namespace lathesim::interp
