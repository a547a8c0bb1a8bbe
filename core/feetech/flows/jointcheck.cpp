// A joint check's verdict: set up, or why not.
#include "jointcheck.h"

#include "motorfinder.h"
#include "motorsetuptr.h"

#include <QCoreApplication>

namespace feetech {

bool JointCheck::done() const
{
    return found && servoIsModel(*found, model) && differing.isEmpty();
}

QString JointCheck::problem() const
{
    if (!found || done())
        return {};
    if (!servoIsModel(*found, model))
        return MotorSetupTr::tr("ID %1 answers as model %2, not %3.")
            .arg(id)
            .arg(found->model.name, model);
    return MotorSetupTr::tr("ID %1 answers, but %2.")
        .arg(id)
        .arg(differing.join(QStringLiteral(", ")));
}

} // namespace feetech
