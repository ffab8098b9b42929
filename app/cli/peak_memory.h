// The process's peak memory, for the --stats of the commands.
#pragma once

namespace app {

// The most resident memory the process has held so far (getrusage's ru_maxrss), in MB (2^20 bytes).
double peakResidentMegabytes();

}  // namespace app
