// Why a file could not be read, checked or saved: a stable code for programs and tests, and the
// translated sentence for people.
#pragma once

#include <QString>

namespace util {

// An empty FileError (code None) is a success. The sentence is built only when asked for, from
// the code and what the error holds: the path, the entry at fault, the offending value and, for
// what only the kind of file can word (a pose's ID out of range, a profile for other servos), a
// detail sentence already translated in that kind's context.
class FileError
{
public:
    // Stable: callers and tests branch on these, never on the sentence.
    enum class Code {
        None,
        CannotRead, // the file system would not give the file (detail: its words)
        TooLarge, // far larger than any file of its kind
        CannotWrite, // the file system would not take the file (detail: its words)
        NotJson, // detail: the parser's words; value: the offset
        NotAnObject, // valid JSON, but no object at the top
        WrongFormat, // "format" names another kind of file, or none
        BadVersion, // "version" is missing or not a whole number
        NewerVersion, // written by a newer ServoBench
        UnknownVersion, // a version below 1 (value)
        UnknownKey, // an entry or parameter the kind does not have (field)
        MissingField, // a required entry is absent (field)
        WrongType, // an entry of the wrong JSON type (field)
        BadValue, // an entry whose value is out of range or not allowed (field, value)
        Duplicate, // the same servo or joint twice
        WrongServos, // written for other servos: another family or model
        NothingToSave, // what would be written is missing or not yet known (no targets, no values)
        NoFileName, // no file was named
    };

    // What was being done with the file, for the sentence: "<file>: <reason>" when reading,
    // "<file> was not saved: <reason>" when saving, "<file>: <reason>; it was not saved" when
    // the check of what was about to be saved refused it, "Could not open <file> for writing:
    // <reason>." for a file written as it goes (a recording).
    enum class Action { Reading, Saving, CheckingSave, Recording };

    FileError() = default;
    explicit FileError(Code code, const QString &detail = {});

    FileError &withField(const QString &field);
    FileError &withValue(const QString &value);
    // The file the error is about; without one, the sentence is the reason alone.
    FileError &inFile(const QString &path, Action action = Action::Reading);

    Code code() const { return m_code; }
    const QString &path() const { return m_path; }
    Action action() const { return m_action; }
    const QString &field() const { return m_field; }
    const QString &value() const { return m_value; }
    const QString &detail() const { return m_detail; }

    explicit operator bool() const { return m_code != Code::None; }

    // What went wrong, without the file: "unknown entry \"speed\"".
    QString reason() const;
    // The whole sentence, naming the file as the platform writes paths: "<file>: <reason>" or
    // "<file> was not saved: <reason>". Empty when there is no error.
    QString describe() const;

private:
    Code m_code = Code::None;
    Action m_action = Action::Reading;
    QString m_path;
    QString m_field;
    QString m_value;
    QString m_detail;
};

// Stores `error` in *out when the caller asked for it (out is not null).
inline void report(FileError *out, const FileError &error)
{
    if (out)
        *out = error;
}

} // namespace util
