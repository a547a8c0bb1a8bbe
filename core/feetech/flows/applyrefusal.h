// Why planApply makes no plan of a servo's pending edits: a code, and a sentence.
#pragma once

#include <QString>

namespace feetech {

// A value type: empty (false) when nothing was refused. Callers and tests decide on code();
// describe() is the translated sentence shown to the user.
class ApplyRefusal
{
public:
    // Stable: callers and tests compare with these, never with the sentence.
    enum class Code {
        None,
        NothingToWrite, // nothing pending in the scope asked for
        IdInUse, // newId(): another servo on the bus answers at it
        BadValue, // detail(): which value cannot be written, and why
    };

    ApplyRefusal() = default;
    explicit ApplyRefusal(Code code)
        : m_code(code)
    { }

    static ApplyRefusal idInUse(int newId);
    static ApplyRefusal badValue(const QString &reason);

    Code code() const { return m_code; }
    explicit operator bool() const { return m_code != Code::None; }
    int newId() const { return m_newId; }
    QString detail() const { return m_detail; }

    QString describe() const;

private:
    Code m_code = Code::None;
    int m_newId = 0;
    QString m_detail;
};

} // namespace feetech
