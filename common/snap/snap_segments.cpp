#include "common/snap/snap_segments.h"

namespace primitive_edit {

SnapOptions fitted_snap_options()
{
  SnapOptions options;
  options.wide_repair = false;
  return options;
}

} // namespace primitive_edit
