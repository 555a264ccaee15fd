// Names and descriptions of the error codes.
#include "volcomp/base/status.hpp"

namespace volcomp {

const char* ErrorName(Error e) {
  switch (e) {
#define X(name, value, text) \
  case Error::name:          \
    return #name;
#include "volcomp/base/error_codes.def"
#undef X
  }
  return "kUnknown";
}

const char* ErrorText(Error e) {
  switch (e) {
#define X(name, value, text) \
  case Error::name:          \
    return text;
#include "volcomp/base/error_codes.def"
#undef X
  }
  return "unknown error";
}

}  // namespace volcomp
