// A recorded motion and its CSV file.
#include "motionrecording.h"

#include "jsonfile.h"
#include "motionrecordingtr.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace feetech {

namespace {

const QString kTimeColumn = QStringLiteral("time_s");
constexpr int kMaxServoId = 253;

util::FileError badValue(const QString &field, const QString &value, const QString &why)
{
    return util::FileError(util::FileError::Code::BadValue, why).withField(field).withValue(value);
}

// The joint a column names: "id_3", or "name@3".
std::optional<MotionJoint> jointOfColumn(const QString &column)
{
    static const QRegularExpression kById(QStringLiteral("^id_(\\d{1,3})$"));
    static const QRegularExpression kNamed(QStringLiteral("^(.+)@(\\d{1,3})$"));
    MotionJoint joint;
    int id = -1;
    if (const auto match = kById.match(column); match.hasMatch()) {
        id = match.captured(1).toInt();
    } else if (const auto named = kNamed.match(column); named.hasMatch()) {
        joint.name = named.captured(1);
        id = named.captured(2).toInt();
    }
    if (id < 0 || id > kMaxServoId)
        return std::nullopt;
    joint.id = quint8(id);
    return joint;
}

} // namespace

int MotionRecording::frameAt(double seconds) const
{
    if (times.isEmpty())
        return -1;
    const double at = times.first() + seconds;
    const auto after = std::upper_bound(times.cbegin(), times.cend(), at);
    return std::max(0, int(after - times.cbegin()) - 1);
}

QByteArray motionRecordingCsv(const MotionRecording &recording)
{
    QStringList header {kTimeColumn};
    for (const MotionJoint &joint : recording.joints)
        header.append(joint.column());
    QByteArray csv = header.join(QLatin1Char(',')).toUtf8() + '\n';
    for (int i = 0; i < recording.frames.size(); ++i) {
        csv += QByteArray::number(recording.times.at(i), 'f', 3);
        for (const qint32 position : recording.frames.at(i)) {
            csv += ',';
            csv += QByteArray::number(position);
        }
        csv += '\n';
    }
    return csv;
}

std::optional<MotionRecording> motionRecordingFromCsv(const QByteArray &csv, util::FileError *error)
{
    const auto fail = [error](const util::FileError &why) -> std::optional<MotionRecording> {
        util::report(error, why);
        return std::nullopt;
    };
    QList<QByteArray> lines = csv.split('\n');
    while (!lines.isEmpty() && lines.last().trimmed().isEmpty())
        lines.removeLast();
    if (lines.isEmpty())
        return fail(util::FileError(
            util::FileError::Code::MissingField,
            MotionRecordingTr::tr("the file is empty: a recording starts with a header "
                                  "line (time_s and one column per joint)")));
    const QStringList header =
        QString::fromUtf8(lines.first().trimmed()).split(QLatin1Char(','), Qt::KeepEmptyParts);
    if (header.first().trimmed() != kTimeColumn)
        return fail(
            util::FileError(util::FileError::Code::MissingField,
                            MotionRecordingTr::tr("the first column of the header is \"%1\", not "
                                                  "time_s: this is not a motion recording")
                                .arg(header.first().trimmed())));
    MotionRecording recording;
    for (int c = 1; c < header.size(); ++c) {
        const QString column = header.at(c).trimmed();
        const auto joint = jointOfColumn(column);
        if (!joint)
            return fail(
                badValue(column, column,
                         MotionRecordingTr::tr("column \"%1\" names no servo: a joint's column is "
                                               "id_N or NAME@N, N its servo's ID (0 to 253)")
                             .arg(column)));
        for (const MotionJoint &known : std::as_const(recording.joints)) {
            if (known.id == joint->id)
                return fail(util::FileError(
                    util::FileError::Code::Duplicate,
                    MotionRecordingTr::tr("servo %1 has two columns").arg(joint->id)));
        }
        recording.joints.append(*joint);
    }
    if (recording.joints.isEmpty())
        return fail(
            util::FileError(util::FileError::Code::MissingField,
                            MotionRecordingTr::tr("the header names no joint after time_s")));
    for (int row = 1; row < lines.size(); ++row) {
        const QString line = QString::fromUtf8(lines.at(row).trimmed());
        const QString where = MotionRecordingTr::tr("line %1").arg(row + 1);
        const QStringList cells = line.split(QLatin1Char(','), Qt::KeepEmptyParts);
        if (cells.size() != header.size())
            return fail(
                badValue(where, line,
                         MotionRecordingTr::tr("line %1 has %2 cells where the header has %3")
                             .arg(row + 1)
                             .arg(cells.size())
                             .arg(header.size())));
        bool ok = false;
        const double time = cells.first().trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(time) || time < 0.0)
            return fail(badValue(
                where, cells.first(),
                MotionRecordingTr::tr("line %1: the time \"%2\" is not a number of seconds "
                                      "from 0")
                    .arg(row + 1)
                    .arg(cells.first().trimmed())));
        if (!recording.times.isEmpty() && time < recording.times.last())
            return fail(
                badValue(where, cells.first(),
                         MotionRecordingTr::tr("line %1: the time goes back, from %2 s to %3 s")
                             .arg(row + 1)
                             .arg(recording.times.last())
                             .arg(time)));
        QVector<qint32> frame;
        for (int c = 1; c < cells.size(); ++c) {
            const double position = cells.at(c).trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(position) || std::abs(position) > 65535)
                return fail(badValue(
                    where, cells.at(c),
                    MotionRecordingTr::tr("line %1: \"%2\" is no position of %3 (a number of "
                                          "steps)")
                        .arg(row + 1)
                        .arg(cells.at(c).trimmed(), recording.joints.at(c - 1).describe())));
            frame.append(qint32(std::lround(position)));
        }
        recording.times.append(time);
        recording.frames.append(frame);
    }
    if (recording.frames.isEmpty())
        return fail(
            util::FileError(util::FileError::Code::MissingField,
                            MotionRecordingTr::tr("the recording has a header but no frame")));
    return recording;
}

std::optional<MotionRecording> loadMotionRecording(const QString &path, util::FileError *error)
{
    const auto read = util::readFile(
        path, MotionRecording::kMaxFileBytes,
        MotionRecordingTr::tr("the file is too large for a motion recording"), error);
    if (!read)
        return std::nullopt;
    util::FileError why;
    auto recording = motionRecordingFromCsv(*read, &why);
    if (!recording)
        util::report(error, why.inFile(path));
    return recording;
}

bool saveMotionRecording(const QString &path, const MotionRecording &recording,
                         util::FileError *error)
{
    if (recording.isEmpty()) {
        util::report(error,
                     util::FileError(util::FileError::Code::NothingToSave,
                                     MotionRecordingTr::tr("nothing was recorded"))
                         .inFile(path, util::FileError::Action::Saving));
        return false;
    }
    return util::writeFileAtomically(path, motionRecordingCsv(recording), error);
}

} // namespace feetech
