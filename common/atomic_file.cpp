#include "atomic_file.h"

#include "grotto/error.h"
#include "file_kind.h"
#include "file_lock.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <regex>
#include <streambuf>
#include <string>
#include <system_error>

namespace grotto {
namespace fs = std::filesystem;

namespace {

// ".NAME.tmpPID-N.EXT" for target NAME.EXT: hidden, unique per process and call.
fs::path temporaryFor(const fs::path& target) {
    static std::atomic<int> counter{0};
    fs::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".tmp" + std::to_string(getpid()) + "-" +
                         std::to_string(counter++) + target.extension().string());
    return tmp;
}

// A stream buffer over a file descriptor that checks every write: the first
// failure's errno is kept and every later write fails too, so the stream goes bad.
class CheckedFileBuf : public std::streambuf {
public:
    explicit CheckedFileBuf(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
    int error() const { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) sputc(traits_type::to_char_type(c));
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (n < epptr() - pptr()) return std::streambuf::xsputn(s, n);
        return drain() && writeAll(s, size_t(n)) ? n : 0;  // large writes skip the buffer
    }
    int sync() override { return drain() ? 0 : -1; }
    // Seekable, for writers that go back to fill in offsets (OpenVDB's archives).
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        if (!drain()) return pos_type(off_type(-1));
        const int whence = dir == std::ios_base::beg ? SEEK_SET : dir == std::ios_base::cur ? SEEK_CUR : SEEK_END;
        return pos_type(off_type(lseek(fd_, off, whence)));
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
        return seekoff(off_type(pos), std::ios_base::beg, which);
    }

private:
    bool drain() {
        const bool ok = writeAll(pbase(), size_t(pptr() - pbase()));
        setp(buffer_, buffer_ + sizeof buffer_);
        return ok;
    }
    bool writeAll(const char* p, size_t n) {
        while (n > 0 && error_ == 0) {
            const ssize_t done = ::write(fd_, p, n);
            if (done < 0 && errno == EINTR) continue;
            if (done <= 0) error_ = done < 0 ? errno : EIO;
            else p += done, n -= size_t(done);
        }
        return error_ == 0;
    }
    int fd_;
    int error_ = 0;
    char buffer_[1 << 16];
};

}  // namespace

void throwWriteFailed(const fs::path& target, int err) {
    const bool full = err == ENOSPC || err == EDQUOT || err == EFBIG;
    throw Error::internal(target.string(), std::string("cannot be written: ") + std::strerror(err),
                          full ? "free some space and run again" : "check the disk and run again");
}

void requireOutputPath(const fs::path& file) {
    fs::path dir = file.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw Error(file.string(), "output directory '" + dir.string() + "' does not exist",
                    "create it first");
    if (access(dir.c_str(), W_OK) != 0)
        throw Error(file.string(), "output directory '" + dir.string() + "' is not writable",
                    "choose a directory you can write to");
    if (const std::string kind = irregularKind(file); !kind.empty())
        throw Error(file.string(), "is " + kind + ", not a regular file",
                    "an output may only replace a regular file; name a file path");
}

PendingFile::PendingFile(const fs::path& target) : target_(target) {
    requireOutputPath(target);
    tmp_ = temporaryFor(target);
    fd_ = open(tmp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd_ < 0 && (errno == ENOSPC || errno == EDQUOT)) throwWriteFailed(target, errno);
    if (fd_ < 0) throw Error(target.string(), std::string("cannot create a temporary file beside it: ") + std::strerror(errno));
    flock(fd_, LOCK_EX);  // held until the rename: the file is not abandoned
}

PendingFile::~PendingFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(tmp_, ec);
    }
    close(fd_);
}

void PendingFile::commit() {
    // On disk before the rename, so neither a crash nor a write the kernel
    // reports late (a full disk seen at writeback) leaves a damaged target.
    if (fsync(fd_) != 0) throwWriteFailed(target_, errno);
    if (rename(tmp_.c_str(), target_.c_str()) != 0) throwWriteFailed(target_, errno);
    committed_ = true;
}

void writeAtomically(const fs::path& target, const std::function<void(std::ostream&)>& write) {
    PendingFile file(target);
    CheckedFileBuf buffer(file.fd());
    std::ostream out(&buffer);
    write(out);
    out.flush();
    if (buffer.error() != 0) throwWriteFailed(target, buffer.error());
    if (!out) throw Error::internal(target.string(), "cannot be written: the stream failed");
    file.commit();
}

void writeAtomically(const fs::path& target, std::string_view bytes) {
    writeAtomically(target, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

int removeAbandonedTemporaries(const fs::path& dir, const std::function<bool(const std::string&)>& ours) {
    static const std::regex pattern(R"(\.(.*)\.tmp([0-9]{1,9})-[0-9]+(\.[^.]*)?)");
    int removed = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        std::smatch m;
        if (!std::regex_match(name, m, pattern) || !ours(m[1].str() + m[3].str())) continue;
        if (const pid_t pid = pid_t(std::stol(m[2].str())); pid > 0 && (kill(pid, 0) == 0 || errno == EPERM))
            continue;  // its process lives: between creating the file and locking it, or still writing
        int fd = -1;
        if (!FileLock::tryHold(entry.path(), fd)) continue;  // a live run is writing it
        std::error_code rm;
        if (fs::remove(entry.path(), rm)) ++removed;
        close(fd);
    }
    return removed;
}

int removeAbandonedTemporariesOf(const fs::path& target) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    return removeAbandonedTemporaries(dir, [name = target.filename().string()](const std::string& t) { return t == name; });
}

}  // namespace grotto
