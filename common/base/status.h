// status.h: the core's one error convention.
//
// Every core operation that can refuse its input returns a Status (or carries one in its result): ok()
// when it did its work, otherwise `error`, one sentence for MeshLab's log that names the problem and,
// where there is one, what the user can do about it. Operations that refuse leave their outputs and the
// mesh untouched. Cost: none (plain data).
#ifndef PRIMITIVE_EDIT_STATUS_H
#define PRIMITIVE_EDIT_STATUS_H

#include <string>
#include <utility>

namespace primitive_edit {

struct Status
{
  std::string error;  // empty when the operation succeeded

  bool ok() const { return error.empty(); }
  explicit operator bool() const { return ok(); }

  static Status success() { return {}; }
  static Status failure(std::string why)
  {
    Status s;
    s.error = why.empty() ? std::string("failed") : std::move(why);
    return s;
  }
};

} // namespace primitive_edit

#endif
