// progress.h: the core's one progress callback.
//
// Progress(percent, what) is called with percent in [0, 100] and a short phrase saying what is being
// done; it returns false to ask the operation to stop (the operation then fails with a Status saying it
// was cancelled, and leaves the mesh untouched). The signature is vcg::CallBackPos's, so MeshLab's
// callback converts to it directly. Operations that use threads call it on the calling thread only, so a
// GUI callback is safe. Cost: whatever the callback costs; the core calls it at most a few hundred times.
#ifndef PRIMITIVE_EDIT_PROGRESS_H
#define PRIMITIVE_EDIT_PROGRESS_H

#include <functional>

namespace primitive_edit {

using Progress = std::function<bool(int percent, const char* what)>;

// Reports to an optional callback; true when the operation should go on.
bool report_progress(const Progress& progress, int percent, const char* what);

// The part [begin, end] of a caller's percent range, for an operation run as one step of a longer one.
Progress progress_range(const Progress& progress, int begin, int end);

} // namespace primitive_edit

#endif
