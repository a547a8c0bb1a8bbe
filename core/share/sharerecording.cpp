// A shared bus's recording: the line format written while sharing and read back by the decoder.
#include "sharerecording.h"

#include "hex.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QTextStream>

namespace share {

namespace {

struct ShareRecordingTr
{
    Q_DECLARE_TR_FUNCTIONS(ShareRecording)
};

const char kMagic[] = "# servobench share recording 1";
constexpr qint64 kLargestRecording = qint64(1) << 30;
// Longer than any share runs (about 31 years), and far inside what microseconds in 64 bits hold.
constexpr double kLatestSecond = 1e9;

std::optional<FrameDirection> directionFromKey(QStringView key)
{
    for (const FrameDirection direction :
         {FrameDirection::FromProgram, FrameDirection::ToProgram, FrameDirection::Own,
          FrameDirection::OwnAnswer, FrameDirection::Note}) {
        if (key == ShareRecording::directionKey(direction))
            return direction;
    }
    return std::nullopt;
}

} // namespace

QString ShareRecording::directionKey(FrameDirection direction)
{
    switch (direction) {
    case FrameDirection::FromProgram:
        return QStringLiteral("program");
    case FrameDirection::ToProgram:
        return QStringLiteral("bus");
    case FrameDirection::Own:
        return QStringLiteral("own");
    case FrameDirection::OwnAnswer:
        return QStringLiteral("own-answer");
    case FrameDirection::Note:
        return QStringLiteral("note");
    }
    return {};
}

util::FileError ShareRecording::open(const QString &path, const QString &port, qint32 baud)
{
    close();
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return util::FileError(util::FileError::Code::CannotWrite, m_file.errorString())
            .inFile(path, util::FileError::Action::Recording);
    m_frames = 0;
    m_error.clear();
    const QByteArray header = QByteArray(kMagic) + "\n# port " + port.toUtf8() + " at "
        + QByteArray::number(baud) + " baud, started "
        + QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toUtf8()
        + "\n# <seconds> program|bus|own|own-answer <hex>, or <seconds> note <text>\n";
    m_file.write(header);
    m_file.flush();
    return {};
}

bool ShareRecording::write(const RecordedFrame &frame)
{
    if (!m_file.isOpen())
        return true;
    QByteArray line = QByteArray::number(double(frame.timeUs) / 1e6, 'f', 6) + ' '
        + directionKey(frame.direction).toLatin1() + ' ';
    line += frame.direction == FrameDirection::Note ? frame.note.toUtf8()
                                                    : util::toHex(frame.bytes).toLatin1();
    line += '\n';
    // Flushed now: a recording must survive the program (or ServoBench) being killed.
    if (m_file.write(line) != line.size() || !m_file.flush()) {
        m_error = m_file.errorString();
        m_file.close();
        return false;
    }
    ++m_frames;
    return true;
}

void ShareRecording::close()
{
    if (m_file.isOpen())
        m_file.close();
}

std::optional<QVector<RecordedFrame>> ShareRecording::load(const QString &path,
                                                           util::FileError *error)
{
    QFile file(path);
    const auto fail = [&](const util::FileError &what) -> std::optional<QVector<RecordedFrame>> {
        util::report(error, util::FileError(what).inFile(path));
        return std::nullopt;
    };
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return fail(util::FileError(util::FileError::Code::CannotRead, file.errorString()));
    if (file.size() > kLargestRecording)
        return fail(
            util::FileError(util::FileError::Code::TooLarge,
                            ShareRecordingTr::tr("it is larger than any recording (1 GiB)")));
    QVector<RecordedFrame> frames;
    int lineNumber = 0;
    bool sawMagic = false;
    while (!file.atEnd()) {
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        ++lineNumber;
        if (line.isEmpty())
            continue;
        if (line.startsWith(QLatin1Char('#'))) {
            sawMagic = sawMagic || line == QLatin1String(kMagic);
            continue;
        }
        const auto badLine = [&] {
            return fail(util::FileError(
                            util::FileError::Code::BadValue,
                            ShareRecordingTr::tr("line %1 is not \"<seconds> <direction> <hex>\"")
                                .arg(lineNumber))
                            .withField(QString::number(lineNumber))
                            .withValue(line.left(60)));
        };
        if (!sawMagic)
            return fail(
                util::FileError(util::FileError::Code::WrongFormat,
                                ShareRecordingTr::tr("this is no ServoBench share recording")));
        const QStringList parts = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (parts.size() < 2)
            return badLine();
        bool ok = false;
        const double seconds = parts.at(0).toDouble(&ok);
        const auto direction = directionFromKey(parts.at(1));
        if (!ok || !(seconds >= 0 && seconds <= kLatestSecond) || !direction)
            return badLine();
        RecordedFrame frame;
        frame.timeUs = qint64(seconds * 1e6 + 0.5);
        frame.direction = *direction;
        if (*direction == FrameDirection::Note) {
            frame.note = line.section(QLatin1Char(' '), 2, -1, QString::SectionSkipEmpty);
        } else {
            const auto bytes = util::parseHex(parts.mid(2));
            if (!bytes || bytes->isEmpty())
                return badLine();
            frame.bytes = *bytes;
        }
        frames.append(frame);
    }
    if (!sawMagic)
        return fail(util::FileError(util::FileError::Code::WrongFormat,
                                    ShareRecordingTr::tr("this is no ServoBench share recording")));
    return frames;
}

} // namespace share
