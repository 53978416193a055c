// seed_queue.h: the faces of a mesh in order of flatness, flattest first, handed out one at a time as the seeds
// of grow_regions.
//
// Input:  GrowingFaces (growing_faces.h), the FaceAdjacency and the threads (parallel_for.h; <= 0: all).
// Output: SeedQueue. next(eligible) gives the next valid face, in the order of (variation, index), for which
//         eligible(f) holds, and -1 after the last. A face's variation is the mean over its neighbours of
//         1 - cos of the angle between their smoothed normals (2 for an invalid neighbour). The caller must never
//         make a face eligible again once eligible(f) was false (grow_regions' seeds are the faces neither
//         assigned nor failed, and faces are only ever assigned or failed): then the faces handed out are those
//         a sort of every face gives, in its order.
// Method: the variations, by the threads; the faces bucketed by the top kSeedBucketBits bits of their key's
//         order-preserving bits (ordered_bits.h), one stable counting pass; a bucket is sorted (stable, by
//         variation) only when the queue reaches it, and only over its faces still eligible then. By then the
//         regions grown from flatter seeds hold most of the faces: a full (radix) sort of every face took a sixth
//         of the region growth on the 1M-face peer part (perf), most of it for faces that were never tried.
// Cost:   O(F) divided by the threads for the variations, O(F + 2^kSeedBucketBits) for the buckets, and the
//         sorts of the faces still eligible when their bucket comes.
#ifndef PRIMITIVE_EDIT_SEED_QUEUE_H
#define PRIMITIVE_EDIT_SEED_QUEUE_H

#include "common/mesh/face_adjacency.h"
#include "common/segment/growing_faces.h"

#include <cstddef>
#include <vector>

namespace primitive_edit {

// 1 sign, 11 exponent and 4 mantissa bits: 16 buckets per octave of the variation.
constexpr int kSeedBucketBits = 16;

class SeedQueue
{
public:
  SeedQueue(const GrowingFaces& g, const FaceAdjacency& adj, int threads = 0);

  template <class Eligible>
  int next(Eligible eligible)
  {
    for (;;) {
      while (at_ < current_.size()) {
        const int f = current_[std::size_t(at_++)];
        if (eligible(f))
          return f;
      }
      if (bucket_ == bucket_end_.size())
        return -1;
      current_.clear();
      at_ = 0;
      for (std::size_t i = bucket_ == 0 ? 0 : bucket_end_[bucket_ - 1]; i < bucket_end_[bucket_]; ++i)
        if (eligible(faces_[i]))
          current_.push_back(faces_[i]);
      ++bucket_;
      sort_current();
    }
  }

  // The share of the faces whose bucket the queue has reached (for progress).
  double share_passed() const;

private:
  void sort_current();

  std::vector<double> variation_;      // per face
  std::vector<int> faces_;             // the valid faces, bucket by bucket, in index order within one
  std::vector<std::size_t> bucket_end_; // the end in faces_ of each bucket that holds faces, in key order
  std::size_t bucket_ = 0;             // buckets handed to current_
  std::vector<int> current_;           // the last bucket's faces still eligible when it came, sorted
  std::size_t at_ = 0;                 // the next of current_
};

} // namespace primitive_edit

#endif
