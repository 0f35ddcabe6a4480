// A process started with stdin, stdout or stderr closed (`doublet ... 2>&-`) would hand
// descriptor 2 to the next file it opens: a temporary output, into which every warning
// printed on "stderr" would then land. Opening /dev/null onto each closed one first keeps
// 0-2 out of the way (what setuid programs and GCC's driver do too).
#pragma once

namespace doublet::cli {

// Opens /dev/null on each of descriptors 0, 1 and 2 that is closed. Call first in main().
void open_closed_standard_fds();

}  // namespace doublet::cli
