#include "files/TemporaryFiles.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include "common/Fnv1a.h"

namespace matevo {

namespace {

constexpr std::string_view kTemporaryMarker = ".matevo-tmp-";
constexpr std::size_t kHostDigits = 16;

std::string firstLineOf(const char* file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// Host name, boot id and PID namespace: together they say where a PID is meaningful. A part
// that cannot be read is left empty; the others still tell hosts apart.
std::string computeHostTag() {
    char host[256] = {};
    (void)::gethostname(host, sizeof host - 1);
    std::string identity = host;
    identity += '\n';
    identity += firstLineOf("/proc/sys/kernel/random/boot_id");
    identity += '\n';
    std::error_code ignored;
    identity += std::filesystem::read_symlink("/proc/self/ns/pid", ignored).string();
    char tag[kHostDigits + 1];
    std::snprintf(tag, sizeof tag, "%016llx",
                  static_cast<unsigned long long>(fnv1a(
                      reinterpret_cast<const unsigned char*>(identity.data()), identity.size())));
    return tag;
}

const std::string& hostTag() {
    static const std::string tag = computeHostTag();
    return tag;
}

bool allDigits(std::string_view text) {
    if (text.empty()) return false;
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

// The PID of a temporary name made on this host, boot and namespace; 0 for any other name.
long ownHostPid(const std::string& name) {
    const auto marker = name.rfind(kTemporaryMarker);
    if (name.empty() || name[0] != '.' || marker == std::string::npos) return 0;
    const std::string_view owner = std::string_view(name).substr(marker + kTemporaryMarker.size());
    // HOST-PID-N
    if (owner.size() < kHostDigits + 4 || owner.substr(0, kHostDigits) != hostTag() ||
        owner[kHostDigits] != '-')
        return 0;
    const std::string_view pidAndCounter = owner.substr(kHostDigits + 1);
    const auto dash = pidAndCounter.find('-');
    if (dash == std::string_view::npos || dash > 9 || !allDigits(pidAndCounter.substr(0, dash)) ||
        !allDigits(pidAndCounter.substr(dash + 1)))
        return 0;
    return std::stol(std::string(pidAndCounter.substr(0, dash)));
}

bool processAlive(long pid) { return ::kill(pid_t(pid), 0) == 0 || errno == EPERM; }

// Fixed storage, as a signal handler may neither allocate nor follow a pointer another thread
// frees. A slot is free (0), being filled (1) or names a file in flight (2).
struct InFlightSlot {
    std::atomic<int> state{0};
    char path[4096];
};
InFlightSlot inFlight[TemporaryFileInFlight::kMaxInFlight];

}  // namespace

std::filesystem::path temporaryPathBeside(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) about "." + std::string.
    std::string name = file.filename().string();
    name.insert(0, 1, '.');
    name += kTemporaryMarker;
    name += hostTag();
    name += '-';
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(counter++);
    return folder / name;
}

int removeStaleTemporaryFilesBeside(const std::filesystem::path& file) {
    return removeStaleTemporaryFiles(file.has_parent_path() ? file.parent_path()
                                                            : std::filesystem::path("."));
}

TemporaryFileInFlight::TemporaryFileInFlight(const std::filesystem::path& temporary) {
    const std::string& text = temporary.native();
    if (text.size() >= sizeof InFlightSlot::path) return;
    for (int slot = 0; slot < kMaxInFlight; ++slot) {
        int expected = 0;
        if (!inFlight[slot].state.compare_exchange_strong(expected, 1)) continue;
        text.copy(inFlight[slot].path, text.size());
        inFlight[slot].path[text.size()] = '\0';
        inFlight[slot].state.store(2);
        slot_ = slot;
        return;
    }
}

TemporaryFileInFlight::~TemporaryFileInFlight() {
    if (slot_ >= 0) inFlight[slot_].state.store(0);
}

void removeTemporaryFilesInFlight() noexcept {
    for (auto& slot : inFlight)
        if (slot.state.load() == 2) ::unlink(slot.path);
}

int removeStaleTemporaryFiles(const std::filesystem::path& folder) {
    int removed = 0;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error)) {
        const long pid = ownHostPid(entry->path().filename().string());
        if (pid <= 0 || processAlive(pid)) continue;
        std::error_code ignored;
        if (std::filesystem::remove_all(entry->path(), ignored) > 0) ++removed;
    }
    return removed;
}

}  // namespace matevo
