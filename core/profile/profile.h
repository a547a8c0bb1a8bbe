// JSON parameter profiles: a servo's settings saved to a file, validated, diffed with the device.
#pragma once

#include "fileerror.h"
#include "parametermodel.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <QVector>

#include <optional>

namespace profile {

// The marker and format version every profile carries. A file with a higher version was written
// by a newer ServoBench and is refused rather than half-understood.
inline constexpr char kFormatMarker[] = "servobench-profile";
inline constexpr int kFormatVersion = 1;

struct ProfileValue
{
    QString key;
    qint64 raw = 0; // device units, as model::ParameterModel holds them

    bool operator==(const ProfileValue &other) const
    {
        return key == other.key && raw == other.raw;
    }
    bool operator!=(const ProfileValue &other) const { return !(*this == other); }
};

struct Profile
{
    QString family; // "ptk", "sts", ...
    QString model; // model name, or empty when the family has only one
    QVector<ProfileValue> values; // in definition order; a partial profile holds only some keys
    QString note; // free text for the user, optional
    QDateTime saved; // when the values were taken; invalid when unknown

    std::optional<qint64> value(const QString &key) const;
};

// One parameter whose file value would change the device.
struct DiffRow
{
    QString key;
    QString label;
    std::optional<qint64> device; // raw; empty when the device value has not been read
    qint64 file = 0; // raw
};

// The profile as an indented JSON document, values in user units (raw × scale); on/off
// parameters (exactly the choices 0 and 1) as true / false. Values whose key is not among
// `definitions` are left out.
QByteArray toJson(const Profile &profile, const QVector<model::Definition> &definitions);

// Writes `profile` to `path` atomically: either the whole new file is there or the old one is
// untouched. Refuses (and writes nothing) a profile that load() would refuse. On failure *error
// says why, naming the file.
bool save(const QString &path, const Profile &profile,
          const QVector<model::Definition> &definitions, util::FileError *error = nullptr);

// Reads a profile, validating all of it (syntax, format, version, family, keys, types, ranges)
// before returning anything: on any problem, nothing and *error says what (load() naming the
// file). Values for read-only parameters are ignored, since a full register dump legitimately
// contains them.
std::optional<Profile> parse(const QByteArray &json, const QString &expectedFamily,
                             const QVector<model::Definition> &definitions,
                             util::FileError *error = nullptr);
std::optional<Profile> load(const QString &path, const QString &expectedFamily,
                            const QVector<model::Definition> &definitions,
                            util::FileError *error = nullptr);

// The writable parameters whose file value differs from the device value or whose device value
// is unknown, in profile order. Pending edits play no part: the diff is device vs file.
QVector<DiffRow> diff(const Profile &profile, const model::ParameterModel &parameters);

// A profile of what `parameters` holds: the pending edit where `preferPending` and there is one,
// else the device value; parameters with neither are left out. Stamped with the current time.
Profile fromModel(const model::ParameterModel &parameters, const QString &family,
                  const QString &modelName, bool preferPending);

} // namespace profile
