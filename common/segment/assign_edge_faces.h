// assign_edge_faces.h: hands the faces a normal-angle fill left out (edge faces, noise_scaled_normals.h) to the
// segments around them.
//
// Input:  the FaceAdjacency, one unit normal per face (zero: undefined), and segment_of_face with -1 on the
//         faces still to assign (and on deleted faces).
// Output: segment_of_face with every face that is connected to a segment through unassigned faces assigned;
//         faces with no segment in their component stay -1, and so do deleted faces, which the adjacency links
//         to nothing.
// Method: rounds, outwards from the segments: in each round every unassigned face next to assigned ones joins
//         the neighbouring face's segment whose normal is closest to its own (ties: the lower segment id).
//         An edge face between two surfaces so goes to the side its smoothed normal leans to, which splits the
//         ramp of a blurred edge near its middle. Each round reads only the previous round's labels, so the
//         result does not depend on the order of the faces.
// Cost:   O(rounds * (F + adjacency size)), rounds = the widest band of unassigned faces; O(F) memory.
#ifndef PRIMITIVE_EDIT_ASSIGN_EDGE_FACES_H
#define PRIMITIVE_EDIT_ASSIGN_EDGE_FACES_H

#include "common/mesh/face_adjacency.h"

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

namespace primitive_edit {

void assign_edge_faces(const FaceAdjacency& adj, const std::vector<Eigen::Vector3d>& normal,
                       std::vector<int>& segment_of_face);

} // namespace primitive_edit

#endif
