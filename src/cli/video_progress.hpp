// The end of a recording, with progress: the frames buffered during a run are rendered after it
// (minutes for a long paced run); this shows a bar with the time left meanwhile, on a terminal.
#pragma once

#include <cstdio>

#include "observers/record_video.hpp"

namespace cerebellum {

// VideoRecorder::finish(), with a progress bar on out while the rest is rendered
VideoResult finish_video_showing_progress(VideoRecorder& recorder, std::FILE* out);

}  // namespace cerebellum
