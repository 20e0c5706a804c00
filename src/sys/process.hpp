// What every command needs of the process before it starts: the three standard streams open,
// and writes that fail with an error instead of a signal.
#pragma once

namespace tumble::sys {

// Opens /dev/null on any of file descriptors 0, 1 and 2 that is closed (`tumble render ...
// 2>&-`): otherwise the next file opened, such as the MP4, would get that number, and progress
// text meant for standard error would be written into the video.
//
// Ignores SIGXFSZ and SIGPIPE, so that a file-size limit (ulimit -f) or a closed pipe (`tumble
// render ... 2>&1 | head -1`) fails a write with an error tumble reports, as a full disk does,
// instead of killing it half way through a render.
void set_up_process();

}  // namespace tumble::sys
