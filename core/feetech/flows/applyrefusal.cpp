// The refusals of the apply plan, and their sentences.
#include "applyrefusal.h"
#include "feetechsessiontr.h"

#include <QCoreApplication>

namespace feetech {

ApplyRefusal ApplyRefusal::idInUse(int newId)
{
    ApplyRefusal refusal(Code::IdInUse);
    refusal.m_newId = newId;
    return refusal;
}

ApplyRefusal ApplyRefusal::badValue(const QString &reason)
{
    ApplyRefusal refusal(Code::BadValue);
    refusal.m_detail = reason;
    return refusal;
}

QString ApplyRefusal::describe() const
{
    switch (m_code) {
    case Code::None:
        return {};
    case Code::NothingToWrite:
        return FeetechSessionTr::tr("Nothing to write.");
    case Code::IdInUse:
        return FeetechSessionTr::tr("ID %1 is already in use on this bus.").arg(m_newId);
    case Code::BadValue:
        return m_detail;
    }
    return {};
}

} // namespace feetech
