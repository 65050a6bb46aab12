#include "engine/core/error.h"

namespace pcsg {

std::string SourceLocation::str() const {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  return s;
}

SceneError::SceneError(const SourceLocation& where, const std::string& what)
    : Error(where.str() + ": " + what), where_(where) {}

}  // namespace pcsg
