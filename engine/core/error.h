#pragma once
// User-facing errors. Every invalid input throws one of these with a message a user can act on:
// the file, the place (line:column), the offending value and what was expected.
#include <stdexcept>
#include <string>

namespace pcsg {

// A place in a source file; line and column are 1-based, 0 when unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  // "file:line:column" with the unknown parts left out.
  std::string str() const;
};

// Base of all errors that reach the user as one line and a non-zero exit.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Invalid scene: syntax, unsupported or invalid geometry, unknown names.
class SceneError : public Error {
 public:
  SceneError(const SourceLocation& where, const std::string& what);
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

// Invalid command-line value (the CLI maps it to exit code 2).
class UsageError : public Error {
 public:
  using Error::Error;
};

}  // namespace pcsg
