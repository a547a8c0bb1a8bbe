// Pseudo-terminal master with a symlink to its slave, for the simulated servos and a shared bus.
#include "pseudoterminal.h"

#include "ptybaud.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSocketNotifier>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>
#endif

namespace {

struct PseudoTerminalTr
{
    Q_DECLARE_TR_FUNCTIONS(PseudoTerminal)
};

} // namespace

namespace seriallink {

namespace {

// While no client holds the slave, the master reads EIO: look again this often, and at first
// more often, for a while: a program that closes the port to open it again at once (LeRobot at
// every connect) must not wait for its first bytes to be read.
constexpr int kHangupPollMs = 20;
constexpr int kQuickPollMs = 2;
constexpr qint64 kQuickPollPeriodMs = 500;

} // namespace

PseudoTerminal::PseudoTerminal(QObject *parent)
    : DevicePort(parent)
{
    m_hangupPoll.setSingleShot(true);
    m_hangupPoll.setTimerType(Qt::PreciseTimer);
    connect(&m_hangupPoll, &QTimer::timeout, this, [this] {
        if (m_readNotifier)
            m_readNotifier->setEnabled(true);
    });
}

PseudoTerminal::~PseudoTerminal()
{
    close();
}

#ifdef Q_OS_UNIX

bool PseudoTerminal::open(const QString &linkPath, QString *error)
{
    close();
    const auto fail = [&](const QString &what) {
        if (error)
            *error = what;
        close();
        return false;
    };
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (master < 0)
        return fail(PseudoTerminalTr::tr("cannot open a pseudo-terminal: %1")
                        .arg(QString::fromLocal8Bit(std::strerror(errno))));
    m_master = master;
    if (::grantpt(master) != 0 || ::unlockpt(master) != 0)
        return fail(PseudoTerminalTr::tr("cannot unlock the pseudo-terminal: %1")
                        .arg(QString::fromLocal8Bit(std::strerror(errno))));
    char name[128] = {};
    if (::ptsname_r(master, name, sizeof name) != 0)
        return fail(PseudoTerminalTr::tr("cannot name the pseudo-terminal's slave"));
    m_slavePath = QString::fromLocal8Bit(name);

    // Raw on the slave from the start, so nothing is echoed or translated before a client
    // configures the port itself.
    const int slave = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (slave >= 0) {
        struct termios settings
        {
        };
        if (::tcgetattr(slave, &settings) == 0) {
            ::cfmakeraw(&settings);
            ::tcsetattr(slave, TCSANOW, &settings);
        }
        ::close(slave);
    }

    const QFileInfo existing(linkPath);
    if (existing.isSymLink()) {
        if (::unlink(QFile::encodeName(linkPath).constData()) != 0)
            return fail(PseudoTerminalTr::tr("cannot replace the old link %1: %2")
                            .arg(linkPath, QString::fromLocal8Bit(std::strerror(errno))));
    } else if (existing.exists()) {
        return fail(
            PseudoTerminalTr::tr("%1 exists and is not a symlink; choose another --link path")
                .arg(linkPath));
    }
    if (::symlink(name, QFile::encodeName(linkPath).constData()) != 0)
        return fail(PseudoTerminalTr::tr("cannot create the link %1: %2")
                        .arg(linkPath, QString::fromLocal8Bit(std::strerror(errno))));
    m_linkPath = linkPath;

    m_readNotifier = new QSocketNotifier(master, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PseudoTerminal::readAvailable);
    m_writeNotifier = new QSocketNotifier(master, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &PseudoTerminal::flushPending);
    return true;
}

void PseudoTerminal::close()
{
    m_hangupPoll.stop();
    delete m_readNotifier;
    m_readNotifier = nullptr;
    delete m_writeNotifier;
    m_writeNotifier = nullptr;
    if (!m_linkPath.isEmpty()) {
        // Only remove the link if it still points at our slave.
        if (QFile::symLinkTarget(m_linkPath) == m_slavePath)
            QFile::remove(m_linkPath);
        m_linkPath.clear();
    }
    if (m_master >= 0) {
        ::close(m_master);
        m_master = -1;
    }
    m_pending.clear();
}

qint32 PseudoTerminal::hostBaudRate() const
{
    return m_master >= 0 ? readSlaveBaudRate(m_master) : 0;
}

void PseudoTerminal::readAvailable()
{
    QByteArray bytes;
    char buffer[4096];
    for (;;) {
        const ssize_t count = ::read(m_master, buffer, sizeof buffer);
        if (count > 0) {
            bytes.append(buffer, count);
            continue;
        }
        if (count < 0 && errno == EINTR)
            continue;
        if (count < 0 && errno == EIO) {
            // No client holds the slave: stop the notifier firing and look again later.
            m_readNotifier->setEnabled(false);
            if (!m_hungUpSince.isValid())
                m_hungUpSince.start();
            m_hangupPoll.start(m_hungUpSince.elapsed() < kQuickPollPeriodMs ? kQuickPollMs
                                                                            : kHangupPollMs);
        }
        break;
    }
    if (!bytes.isEmpty()) {
        m_hungUpSince.invalidate(); // a client is there: the next hang-up starts a quick look
        emit received(bytes);
    }
}

void PseudoTerminal::write(const QByteArray &bytes)
{
    if (m_master < 0 || bytes.isEmpty())
        return;
    m_pending.append(bytes);
    flushPending();
}

void PseudoTerminal::flushPending()
{
    while (!m_pending.isEmpty()) {
        const ssize_t count = ::write(m_master, m_pending.constData(), size_t(m_pending.size()));
        if (count > 0) {
            m_pending.remove(0, count);
            continue;
        }
        if (count < 0 && errno == EINTR)
            continue;
        if (count < 0 && errno == EIO) {
            m_pending.clear(); // nobody is listening: a real wire would lose these bytes too
            break;
        }
        break; // EAGAIN: the pty buffer is full
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(!m_pending.isEmpty());
}

#else

// Windows has no pseudo-terminals: the simulated servos cannot be offered as a port there, and
// whoever starts them (servosim, the GUI's demo) shows this message.
bool PseudoTerminal::open(const QString &, QString *error)
{
    if (error)
        *error = PseudoTerminalTr::tr(
            "Simulated servos need a pseudo-terminal, which this system does not "
            "have: they run on Linux and macOS.");
    return false;
}

void PseudoTerminal::close() { }

qint32 PseudoTerminal::hostBaudRate() const
{
    return 0;
}

void PseudoTerminal::readAvailable() { }

void PseudoTerminal::write(const QByteArray &) { }

void PseudoTerminal::flushPending() { }

#endif // Q_OS_UNIX

} // namespace seriallink
