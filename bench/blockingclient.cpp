// A Feetech client in plain POSIX calls, blocking, like the vendors' SDKs: open, write, read.
#include "blockingclient.h"

#include <QFile>

#include <cerrno>
#include <cstring>

#include <asm/termbits.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace bench {

namespace {

int frameLength(const QByteArray &buffer)
{
    if (buffer.size() < 4)
        return 0;
    return 4 + quint8(buffer.at(3));
}

} // namespace

BlockingClient::~BlockingClient()
{
    close();
}

bool BlockingClient::open(const QString &path, qint32 baud)
{
    close();
    m_fd = ::open(QFile::encodeName(path).constData(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_fd < 0) {
        m_error = QString::fromLocal8Bit(std::strerror(errno));
        return false;
    }
    ::ioctl(m_fd, TIOCEXCL);
    if (!setBaudRate(baud)) {
        close();
        return false;
    }
    return true;
}

bool BlockingClient::setBaudRate(qint32 baud)
{
    struct termios2 settings
    {
    };
    if (::ioctl(m_fd, TCGETS2, &settings) != 0) {
        m_error = QString::fromLocal8Bit(std::strerror(errno));
        return false;
    }
    // Raw 8N1, any rate (BOTHER), reads that return what is there.
    settings.c_iflag = 0;
    settings.c_oflag = 0;
    settings.c_lflag = 0;
    settings.c_cflag = CS8 | CREAD | CLOCAL | BOTHER;
    settings.c_ispeed = speed_t(baud);
    settings.c_ospeed = speed_t(baud);
    settings.c_cc[VMIN] = 0;
    settings.c_cc[VTIME] = 0;
    if (::ioctl(m_fd, TCSETS2, &settings) != 0) {
        m_error = QString::fromLocal8Bit(std::strerror(errno));
        return false;
    }
    return true;
}

void BlockingClient::close()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
    m_buffer.clear();
}

QVector<QByteArray> BlockingClient::exchange(const QByteArray &request, int answers,
                                             std::chrono::milliseconds timeout)
{
    QVector<QByteArray> frames;
    if (m_fd < 0)
        return frames;
    m_buffer.clear();
    qsizetype written = 0;
    while (written < request.size()) {
        const ssize_t count =
            ::write(m_fd, request.constData() + written, size_t(request.size() - written));
        if (count < 0 && errno == EINTR)
            continue;
        if (count <= 0)
            return frames;
        written += count;
    }
    bool echoSkipped = false;
    while (frames.size() < answers) {
        // Frames complete in what is buffered come out first.
        while (m_buffer.size() >= 2
               && !(quint8(m_buffer.at(0)) == 0xFF && quint8(m_buffer.at(1)) == 0xFF))
            m_buffer.remove(0, 1);
        const int length = frameLength(m_buffer);
        if (length > 0 && m_buffer.size() >= length) {
            const QByteArray frame = m_buffer.left(length);
            m_buffer.remove(0, length);
            if (!echoSkipped && frame == request && frames.isEmpty()) {
                echoSkipped = true;
                continue;
            }
            frames.append(frame);
            continue;
        }
        pollfd ready {m_fd, POLLIN, 0};
        const int polled = ::poll(&ready, 1, int(timeout.count()));
        if (polled < 0 && errno == EINTR)
            continue;
        if (polled <= 0)
            break;
        char bytes[512];
        const ssize_t count = ::read(m_fd, bytes, sizeof bytes);
        if (count <= 0)
            break;
        m_buffer.append(bytes, count);
    }
    return frames;
}

std::optional<QByteArray> BlockingClient::ask(const QByteArray &request, quint8 id,
                                              std::chrono::milliseconds timeout)
{
    const QVector<QByteArray> frames = exchange(request, 1, timeout);
    for (const QByteArray &frame : frames) {
        if (quint8(frame.at(2)) == id)
            return frame;
        ++m_unexpected;
    }
    return std::nullopt;
}

} // namespace bench
