#include "common/fit/fit_result.h"

namespace primitive_edit {

const char* fit_method_name(FitMethod method)
{
  switch (method) {
  case FitMethod::Refined: return "Refined starts";
  case FitMethod::Direct: return "Direct (paper)";
  case FitMethod::DirectRefined: return "Direct, refined";
  }
  return "unknown";
}

} // namespace primitive_edit
