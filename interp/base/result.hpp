#pragma once
// Expected failures as values: a located error, and a value-or-error result.
// Inner stages know only line and column; interpret() adds the file name and source line.

#include <string>
#include <utility>
#include <variant>

namespace lathesim::interp {

/// An error in the program text, before the file name and source line are attached.
struct Error {
  int line = 0;    // 1-based
  int column = 0;  // 1-based, in UTF-8 code points
  std::string message;
  std::string file = {};  // the file it is in when not the program's own (an external subprogram)
};

/// Either a T or the Error that prevented it.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : content_(std::move(value)) {}          // NOLINT: implicit by design
  Result(Error error) : content_(std::move(error)) {}      // NOLINT: implicit by design

  bool ok() const { return std::holds_alternative<T>(content_); }
  const T& value() const& { return std::get<T>(content_); }
  T& value() & { return std::get<T>(content_); }
  T&& value() && { return std::get<T>(std::move(content_)); }
  const Error& error() const { return std::get<Error>(content_); }

 private:
  std::variant<T, Error> content_;
};

/// A Result with no value: success, or the Error.
struct Done {};
using Status = Result<Done>;
inline Status success() { return Done{}; }

}  // namespace lathesim::interp
