#pragma once
// Where core's notices and progress go. The command line sets the sinks (app/Messages.h): notices
// as one "matevo COMMAND: TEXT" line each, progress redrawn in place only when stderr is a
// terminal (a redirected log gets no `\r` updates), both silenced by --quiet. Until then, notices
// go to stderr with "matevo: " and progress nowhere.
#include <cstdio>
#include <string>
#include <string_view>

namespace matevo {

using StatusSink = void (*)(std::string_view text);

namespace detail {
inline void noticeToStderr(std::string_view text) {
    std::fprintf(stderr, "matevo: %.*s\n", int(text.size()), text.data());
}
inline void progressNowhere(std::string_view) {}
inline StatusSink noticeSink = noticeToStderr;
inline StatusSink progressSink = progressNowhere;
}  // namespace detail

inline void setStatusSinks(StatusSink notice, StatusSink progress) {
    detail::noticeSink = notice;
    detail::progressSink = progress;
}

// Something worth one line: "building the FGD/TIR tables (once; cached in ...)".
inline void notice(std::string_view text) { detail::noticeSink(text); }
// How far a long step has come, e.g. "tables  42%"; each call replaces the previous one, and an
// empty text ends the line.
inline void progress(std::string_view text) { detail::progressSink(text); }

}  // namespace matevo
