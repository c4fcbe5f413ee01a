#pragma once
// A pre-flight check of VTK XML files (.vtu) for the few values that VTK 9.1's reader
// trusts without checking, so that damaged or hostile files give an error instead of a
// crash or a huge allocation. Private to resect_scenario (used by vtu_io.cpp).

#include "core/status.h"

#include <string>

namespace resect::detail {

/// Checks, without VTK:
///  - the NumberOfPoints / NumberOfCells declared by each Piece are at most what a file of
///    this size can hold (see kMaxItemsPerFileByte in the .cpp);
///  - for compressed files, the compression header of every binary DataArray (appended raw,
///    appended base64 and inline base64): block count, block sizes and compressed sizes
///    must be consistent and fit in the file. VTK divides by the block size and indexes its
///    block tables with these values unchecked (a zero block size crashes it with SIGFPE).
/// Errors name the file. A file VTK cannot parse at all is left to VTK to report.
Status checkVtkXmlFile(const std::string& path);

} // namespace resect::detail
