// Identify's question: what moves, how, and that it is put back.
#include "identifyquestion.h"

#include "jointidentify.h"
#include "skippablequestion.h"

#include <QCoreApplication>

namespace {

struct IdentifyQuestionTr
{
    Q_DECLARE_TR_FUNCTIONS(IdentifyQuestion)
};

} // namespace

bool confirmIdentify(QWidget *parent, const QString &servo)
{
    const SkippableQuestion question(QStringLiteral("identify"),
                                     IdentifyQuestionTr::tr("Identify a servo"),
                                     IdentifyQuestionTr::tr("Move it"));
    return question.ask(
        parent,
        IdentifyQuestionTr::tr(
            "Identify moves %1: its torque comes on and it turns %2 steps each way, slowly "
            "and with little torque, then goes back where it was, its settings as before."
            "\n\nKeep hands and objects clear of the arm. Move it now?")
            .arg(servo)
            .arg(feetech::JointIdentify::kAmplitude));
}
