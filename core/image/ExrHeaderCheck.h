#pragma once
// A check of an OpenEXR file's headers before OpenEXR reads them. OpenEXR 3.1 allocates every
// header attribute at the size the file claims before reading it, so a file of a few hundred
// bytes can make it allocate and fill up to 2 GiB (found by tests/fuzz/FuzzImage.cpp). Here
// the attributes are walked as OpenEXR reads them (known types by their own size, whatever the
// file declares) and each must fit in the bytes that follow it, so what OpenEXR allocates for
// headers is bounded by the file's size. OpenEXR also allocates the buffers of one block of
// pixels on opening, sized by the data window, the compression and the tiles the header claims:
// those are checked against the memory limit (common/MemoryBudget.h).
#include <string>
#include <string_view>

#include "common/Result.h"

namespace matevo {

// Walks the attribute list of each header (all parts of a multi-part file). An Error says what
// is wrong, without the file name, e.g. "header attribute 'comments' claims 1851222292 bytes,
// the file has 310 left". Files that do not start with the OpenEXR magic number pass: OpenEXR
// refuses them itself without allocating.
Status checkExrHeaders(std::string_view bytes);

}  // namespace matevo
