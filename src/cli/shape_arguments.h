// Parsing of the CAD options of `tquad mesh`: --faces LIST and --corners FACE:V1,V2,...
#pragma once

#include <map>
#include <string>
#include <vector>

namespace tquad {

// "0,2,5-7" -> {0, 2, 5, 6, 7}. Throws InputError naming the bad item, or a face
// at or above face_count (before a range is expanded).
std::vector<int> parse_face_list(const std::string& text, int face_count);

// Each "FACE:V1,V2[,V3[,V4]]" -> corners[FACE] = {V1, V2, ...}. Throws InputError.
std::map<int, std::vector<int>> parse_corner_specs(const std::vector<std::string>& specs);

}  // namespace tquad
