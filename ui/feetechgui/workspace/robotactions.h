// The Robot actions of the Feetech workspace: identify a joint, apply a profile or a template's
// settings to the servos selected in the tree, save a robot template. The main window's Robot
// menu and the servo tree's context menu show the same actions.
#pragma once

#include "settingsfile.h"

#include <QObject>
#include <QPointer>

class BatchResultDialog;
class FeetechWorkspace;
class QAction;
class QMenu;
class QProgressDialog;

namespace feetech {
class BatchProgram;
class BusClient;
class Refusal;
struct OperationResult;
} // namespace feetech

class RobotActions : public QObject
{
    Q_OBJECT

public:
    RobotActions(feetech::BusClient *client, FeetechWorkspace *workspace);

    QAction *identifyAction() const { return m_identify; }
    QAction *applyProfileAction() const { return m_applyProfile; }
    QAction *applyTemplateAction() const { return m_applyTemplate; }
    QAction *saveTemplateAction() const { return m_saveTemplate; }
    QList<QAction *> actions() const;
    void addTo(QMenu *menu) const;

    // Identifies servo `index` (BusClient numbering); false and *refusal when refused.
    bool identify(int index, feetech::Refusal *refusal = nullptr);
    // Programs the servos selected in the tree with `file`; the result table opens at the end.
    bool applyToSelected(const feetech::SettingsFile &file, QString *error = nullptr);
    feetech::BatchProgram *batch() const { return m_batch; }
    BatchResultDialog *resultDialog() const; // the last one shown, while it is open

    void chooseProfileToApply();
    void chooseTemplateToApply();
    void openSaveTemplateDialog();

signals:
    void problem(const QString &message);
    void message(const QString &message);

private:
    void updateActions();
    void onBatchFinished();

    feetech::BusClient *m_client = nullptr;
    FeetechWorkspace *m_workspace = nullptr;
    feetech::BatchProgram *m_batch = nullptr;
    QAction *m_identify = nullptr;
    QAction *m_applyProfile = nullptr;
    QAction *m_applyTemplate = nullptr;
    QAction *m_saveTemplate = nullptr;
    QPointer<QProgressDialog> m_progress;
    QPointer<BatchResultDialog> m_results;
    QString m_batchSource;
};
