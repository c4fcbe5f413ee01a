#pragma once
// A pre-flight check of surface files for the damage that Debian's assimp 5.2 does not
// survive: it hangs, crashes or allocates without bound on it. Every case was found by
// fuzzing (fuzz/, README "Fuzzing") and has its inputs in tests/fuzz_regressions/surface_*.
// Private to resect_scenario (used by surface_io.cpp).

#include "core/status.h"

#include <string>

namespace resect::detail {

/// Checks, without assimp, every file that assimp may read as
///  - PLY: the header has an end_header line; element counts are at most the file size;
///    the data holds every element the header declares, and no list declares more values
///    than the rest of the file can hold (assimp loops over a truncated header forever and
///    over a list count of 48 million in a 200-byte file for seconds, allocating gigabytes);
///  - OFF: the dimension and counts are at most the file size (assimp allocates and
///    initialises its arrays from them first);
///  - glTF (text or binary): the JSON is valid, every mesh primitive has a POSITION
///    attribute and none is a LINE_LOOP (assimp dereferences a null pointer for a LINE_LOOP
///    without positions or with damaged ones).
/// Errors name the file. Files of other formats, and damage assimp reports itself, are left
/// to assimp.
Status checkAssimpInput(const std::string& path);

} // namespace resect::detail
