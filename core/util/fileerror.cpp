// FileError: the translated sentence for each code.
#include "fileerror.h"

#include <QCoreApplication>
#include <QDir>

namespace util {

FileError::FileError(Code code, const QString &detail)
    : m_code(code)
    , m_detail(detail)
{ }

FileError &FileError::withField(const QString &field)
{
    m_field = field;
    return *this;
}

FileError &FileError::withValue(const QString &value)
{
    m_value = value;
    return *this;
}

FileError &FileError::inFile(const QString &path, Action action)
{
    m_path = path;
    m_action = action;
    return *this;
}

QString FileError::reason() const
{
    // The messages keep the "util" context they have always had, so their translations apply.
    switch (m_code) {
    case Code::None:
        return {};
    case Code::NotJson:
        return QCoreApplication::translate("util", "not valid JSON: %1 at offset %2")
            .arg(m_detail, m_value);
    case Code::BadVersion:
        return QCoreApplication::translate("util",
                                           "the format version is missing or not a whole number");
    case Code::UnknownVersion:
        return QCoreApplication::translate("util", "unknown format version %1").arg(m_value);
    case Code::UnknownKey:
        if (m_detail.isEmpty())
            return QCoreApplication::translate("util", "unknown entry \"%1\"").arg(m_field);
        break;
    case Code::CannotRead:
    case Code::TooLarge:
    case Code::CannotWrite:
    case Code::NotAnObject:
    case Code::WrongFormat:
    case Code::NewerVersion:
    case Code::MissingField:
    case Code::WrongType:
    case Code::BadValue:
    case Code::Duplicate:
    case Code::WrongServos:
    case Code::NothingToSave:
    case Code::NoFileName:
        break;
    }
    return m_detail;
}

QString FileError::describe() const
{
    if (m_code == Code::None)
        return {};
    if (m_path.isEmpty())
        return reason();
    const QString shown = QDir::toNativeSeparators(m_path);
    const QString named = QCoreApplication::translate("util", "%1: %2").arg(shown, reason());
    switch (m_action) {
    case Action::Reading:
        break;
    case Action::Saving:
        return QCoreApplication::translate("util", "%1 was not saved: %2").arg(shown, reason());
    case Action::CheckingSave:
        return QCoreApplication::translate("util", "%1; it was not saved").arg(named);
    case Action::Recording:
        return QCoreApplication::translate("util", "Could not open %1 for writing: %2.")
            .arg(shown, reason());
    }
    return named;
}

} // namespace util
