#include "ProgressBar.h"

#include <unistd.h>

#include <algorithm>

#include "Messages.h"

namespace matevo::cli {

namespace {
constexpr int kBarWidth = 40;
}

ProgressBar::ProgressBar(int total, std::FILE* stream)
    : stream_(stream),
      enabled_(::isatty(::fileno(stream)) != 0 && !quiet()),
      total_(std::max(total, 1)) {}

ProgressBar::~ProgressBar() {
    if (drawn_) std::fputc('\n', stream_);
}

void ProgressBar::update(int done, const std::string& label) {
    if (!enabled_) return;
    done = std::clamp(done, 0, total_);
    const int filled = done * kBarWidth / total_;
    const int percent = done * 100 / total_;
    if (percent == lastPercent_ && label == lastLabel_) return;
    lastPercent_ = percent;
    lastLabel_ = label;
    std::fprintf(stream_, "\r[%s%s] %3d%% %d/%d %s\x1b[K",
                 std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(kBarWidth - filled), '.').c_str(), percent, done, total_,
                 label.c_str());
    std::fflush(stream_);
    drawn_ = true;
}

}  // namespace matevo::cli
