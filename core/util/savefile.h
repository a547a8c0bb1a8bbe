// Saving a file so that it is there whole or not at all, without clobbering a device or a pipe.
#pragma once

#include <QFileDevice>
#include <QString>

#include <memory>

namespace util {

// A file being saved. A regular file (or a new one) goes through QSaveFile: it takes its name
// only at commit(), so a failed save (a read-only folder, a full disk) leaves the old file
// untouched and no partial one. A path that names a device or a pipe (/dev/stdout, a FIFO) is
// written directly: renaming a finished file over it would replace the device node itself.
// (Opening a FIFO that nobody reads waits for a reader, as any program writing to it would.)
class SavingFile
{
public:
    explicit SavingFile(const QString &path);
    ~SavingFile(); // discards what was not committed

    SavingFile(const SavingFile &) = delete;
    SavingFile &operator=(const SavingFile &) = delete;

    bool open(QIODevice::OpenMode mode);
    QFileDevice &device() { return *m_device; }
    // Flushes and puts the file in place; false when any write or the final step failed.
    bool commit();
    // Gives up: the file is not put in place (a direct write keeps what was written).
    void cancel();
    QString errorString() const { return m_device->errorString(); }

private:
    std::unique_ptr<QFileDevice> m_device;
    bool m_direct = false;
};

} // namespace util
