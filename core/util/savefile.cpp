// SavingFile: QSaveFile for files, a direct write for devices and pipes.
#include "savefile.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace util {

SavingFile::SavingFile(const QString &path)
{
    const QFileInfo info(path);
    m_direct = info.exists() && !info.isFile() && !info.isDir();
    if (m_direct)
        m_device = std::make_unique<QFile>(path);
    else
        m_device = std::make_unique<QSaveFile>(path);
}

// QSaveFile discards an uncommitted file on its own; QFile closes.
SavingFile::~SavingFile() = default;

bool SavingFile::open(QIODevice::OpenMode mode)
{
    return m_device->open(mode);
}

bool SavingFile::commit()
{
    // Writes are buffered: a full disk shows only when the buffer goes out. QSaveFile's own
    // commit() does not notice a failure of that last write (Qt 6.4 put an empty file in place
    // on a full disk), so the buffer is flushed and checked first.
    const bool written = m_device->flush() && m_device->error() == QFileDevice::NoError;
    if (!written) {
        // Not cancel(): it would replace the reason with its own. Uncommitted, the file is
        // discarded when this goes.
        if (m_direct)
            m_device->close();
        return false;
    }
    if (m_direct) {
        m_device->close();
        return m_device->error() == QFileDevice::NoError;
    }
    return static_cast<QSaveFile &>(*m_device).commit();
}

void SavingFile::cancel()
{
    // Never close() a QSaveFile (Qt refuses it): cancelled, its destructor removes the rest.
    if (m_direct)
        m_device->close();
    else
        static_cast<QSaveFile &>(*m_device).cancelWriting();
}

} // namespace util
