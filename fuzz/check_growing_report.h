// check_growing_report.h: the invariants of segment_by_primitive_growing's report that the targets running it
// (fuzz_common, fuzz_segment) share: a primitive slot per segment, a finite roughness and tolerance, and every
// carved blend a segment with a valid primitive between two other segments.
#ifndef PRIMITIVE_EDIT_FUZZ_CHECK_GROWING_REPORT_H
#define PRIMITIVE_EDIT_FUZZ_CHECK_GROWING_REPORT_H

#include "common/segment/segment_by_primitive_growing.h"
#include "fuzz/fuzz_input.h"

#include <cmath>
#include <cstddef>

namespace fuzz {

inline void check_growing_report(const primitive_edit::SegmentByPrimitiveGrowingReport& report, int G)
{
  using primitive_edit::SegmentBlendRecord;
  FUZZ_CHECK(report.primitive_of_segment.size() == std::size_t(G));
  FUZZ_CHECK(std::isfinite(report.roughness) && report.roughness >= 0 && report.tolerance >= 0);
  for (const SegmentBlendRecord& b : report.blends)
    FUZZ_CHECK(b.segment >= 0 && b.segment < G && b.plane_a >= 0 && b.plane_a < G && b.plane_b >= 0 &&
               b.plane_b < G && b.segment != b.plane_a && b.segment != b.plane_b && b.plane_a != b.plane_b &&
               report.primitive_of_segment[std::size_t(b.segment)] &&
               primitive_is_valid(*report.primitive_of_segment[std::size_t(b.segment)]));
}

} // namespace fuzz

#endif
