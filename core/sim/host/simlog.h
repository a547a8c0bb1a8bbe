// The simulator's frame log: one line per frame in or out, hex, timestamped, flushed at once.
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>

namespace sim {

// Line format: "<seconds since start, 6 decimals> <direction> <HEX BYTES>[  # note]", where the
// direction is in, out, echo or drop; "hand" lines carry no bytes, only what the hand did.
class SimLog
{
public:
    bool open(const QString &path, QString *error);
    bool isOpen() const { return m_file.isOpen(); }
    void write(qint64 timeUs, const char *direction, const QByteArray &bytes,
               const QString &note = {});

private:
    QFile m_file;
};

} // namespace sim
