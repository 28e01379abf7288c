#pragma once
// A one-line progress bar on stderr, redrawn in place ("\r") only when it changes, and only when
// stderr is a terminal so that logs and tests get no control characters, and not with --quiet.
#include <cstdio>
#include <string>

namespace matevo::cli {

class ProgressBar {
public:
    explicit ProgressBar(int total, std::FILE* stream = stderr);
    ~ProgressBar();  // ends the line if one was drawn
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // done of the total; label says what is being worked on.
    void update(int done, const std::string& label);

private:
    std::FILE* stream_;
    bool enabled_;
    int total_;
    int lastPercent_ = -1;
    std::string lastLabel_;
    bool drawn_ = false;
};

}  // namespace matevo::cli
