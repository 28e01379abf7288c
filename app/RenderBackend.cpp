#include "RenderBackend.h"

#include "CommandLine.h"

namespace matevo::cli {

RenderBackend parseRenderBackend(const std::string& text, const std::string& option) {
    if (text == "gpu") return RenderBackend::Gpu;
    if (text == "cpu") return RenderBackend::Cpu;
    throw UsageError(option + ": expected gpu or cpu, got " + text);
}

}  // namespace matevo::cli
