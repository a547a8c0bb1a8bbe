// A shared bus's recording: every frame with its time and direction, written as it passes.
#pragma once

#include "fileerror.h"

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QVector>

#include <optional>

namespace share {

// Where a frame went. The program's requests go to the bus; the bus's bytes go back to the
// program; ServoBench's own requests (the watch's reads) and their answers never reach it.
enum class FrameDirection { FromProgram, ToProgram, Own, OwnAnswer, Note };

struct RecordedFrame
{
    qint64 timeUs = 0; // since the share began
    FrameDirection direction = FrameDirection::FromProgram;
    QByteArray bytes; // a frame, or bytes that make none, exactly as they passed
    QString note; // a Note line's text (a rate change, the program closing the port, an alert)
};

// One line per frame: "<seconds, 6 decimals> <direction> <HEX>", direction one of program,
// bus, own, own-answer; "<seconds> note <text>" for what happened; lines starting with # are
// comments (the header says what was shared and when).
class ShareRecording
{
public:
    // Creates the file (replacing one) and writes the header; a FileError (Recording) when not.
    util::FileError open(const QString &path, const QString &port, qint32 baud);
    bool isOpen() const { return m_file.isOpen(); }
    // Appends the frame's line; false when the file refused it (a full disk, a device gone),
    // which closes the recording: what it holds stays readable, and error() says why.
    bool write(const RecordedFrame &frame);
    QString error() const { return m_error; }
    void close();
    qint64 framesWritten() const { return m_frames; }

    // Reads a recording back, frame by frame; a FileError naming the line at fault when the
    // file cannot be read or is no recording.
    static std::optional<QVector<RecordedFrame>> load(const QString &path, util::FileError *error);
    static QString directionKey(FrameDirection direction);

private:
    QFile m_file;
    qint64 m_frames = 0;
    QString m_error;
};

} // namespace share
