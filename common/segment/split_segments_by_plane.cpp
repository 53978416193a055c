#include "common/segment/split_segments_by_plane.h"

namespace primitive_edit {

namespace split_detail {

void absorb_small_pieces(const FaceAdjacency& adj, const std::vector<int>& former, int first_piece,
                         int min_faces, std::vector<int>& segment_of_face)
{
  if (min_faces <= 1 || segment_of_face.empty())
    return;
  const int end = *std::max_element(segment_of_face.begin(), segment_of_face.end()) + 1;
  if (end <= first_piece)
    return;
  const auto piece_count = std::size_t(end - first_piece);
  std::vector<int> size(piece_count, 0);
  for (const int s : segment_of_face)
    if (s >= first_piece)
      ++size[std::size_t(s - first_piece)];
  std::map<std::pair<int, int>, int> shared;  // (small piece, neighbouring piece) -> edges
  for (std::size_t f = 0; f < segment_of_face.size(); ++f) {
    const int piece = segment_of_face[f];
    if (piece < first_piece || size[std::size_t(piece - first_piece)] >= min_faces)
      continue;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
      const std::size_t g = std::size_t(adj.neighbour[std::size_t(k)]);
      if (segment_of_face[g] >= first_piece && segment_of_face[g] != piece && former[g] == former[f])
        ++shared[{piece, segment_of_face[g]}];
    }
  }
  std::vector<int> into(piece_count);
  for (std::size_t i = 0; i < piece_count; ++i)
    into[i] = first_piece + int(i);
  auto find = [&](int piece) {
    while (into[std::size_t(piece - first_piece)] != piece)
      piece = into[std::size_t(piece - first_piece)];
    return piece;
  };
  for (auto it = shared.begin(); it != shared.end();) {
    const int piece = it->first.first;
    int best = -1, best_edges = 0;
    for (; it != shared.end() && it->first.first == piece; ++it)
      if (it->second > best_edges) {
        best = it->first.second;
        best_edges = it->second;
      }
    const int root = find(best);
    if (root != piece)
      into[std::size_t(piece - first_piece)] = root;
  }
  // A piece still small after that (one that touches no other piece of its segment, such as faces that lay apart
  // from the segment's body before the cut, or a cluster of small pieces) joins the segment's largest piece
  // instead of becoming a segment of a few faces.
  std::vector<int> former_of(piece_count, -1);
  for (std::size_t f = 0; f < segment_of_face.size(); ++f)
    if (segment_of_face[f] >= first_piece)
      former_of[std::size_t(segment_of_face[f] - first_piece)] = former[f];
  std::map<int, int> largest;  // former segment -> its largest piece
  for (std::size_t i = 0; i < piece_count; ++i) {
    auto [it, added] = largest.emplace(former_of[i], first_piece + int(i));
    if (!added && size[i] > size[std::size_t(it->second - first_piece)])
      it->second = first_piece + int(i);
  }
  std::vector<int> joined(piece_count, 0);
  for (std::size_t i = 0; i < piece_count; ++i)
    joined[std::size_t(find(first_piece + int(i)) - first_piece)] += size[i];
  for (std::size_t i = 0; i < piece_count; ++i) {
    const int piece = first_piece + int(i);
    if (into[i] == piece && joined[i] < min_faces) {
      const int root = find(largest[former_of[i]]);
      if (root != piece)
        into[i] = root;
    }
  }
  for (int& s : segment_of_face)
    if (s >= first_piece)
      s = find(s);
}

} // namespace split_detail
} // namespace primitive_edit
