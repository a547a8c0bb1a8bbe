// A parameter form: grouped rows of device value, editor, unit and state, bound to a parameter
// model.
#pragma once

#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace model {
class ParameterModel;
struct Definition;
} // namespace model

// Binds editors to a model::ParameterModel by hand (no QDataWidgetMapper, which would overwrite
// what the user is typing): edits go to the model as they are typed, and device updates reach
// an editor only while the user is not typing in it.
class ParameterPage : public QWidget
{
    Q_OBJECT

public:
    struct Options
    {
        QString objectName = QStringLiteral("parameterPage");
        QString intro; // a line above the form; empty: the default explanation
        QStringList keys; // the parameters to show; empty: all of them
        int columns = 2; // of group boxes, side by side
        QString emptyText; // shown instead of the form while there is no model
    };

    // The form follows the model's definitions, and rebuilds itself if they are set again.
    explicit ParameterPage(model::ParameterModel *model, QWidget *parent = nullptr);
    ParameterPage(model::ParameterModel *model, const Options &options, QWidget *parent = nullptr);

    // Shows another model's parameters (another servo); null leaves the form empty.
    void setModel(model::ParameterModel *model);
    model::ParameterModel *parameterModel() const { return m_model; }

    // The servo answers: Read and Apply may be used.
    void setLinkReady(bool ready);
    bool isLinkReady() const { return m_linkReady; }
    // An Apply is in progress: editors and buttons are disabled and `what` is shown.
    void setBusy(bool busy, const QString &what = QString());
    bool isBusy() const { return m_busy; }
    void setProgress(int done, int total);

    // For tests and for the main window to focus a parameter.
    QWidget *editor(const QString &key) const;
    QLabel *deviceLabel(const QString &key) const;
    QLabel *stateLabel(const QString &key) const;

signals:
    void readRequested();
    void applyRequested();
    void saveProfileRequested();
    void loadProfileRequested();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Row
    {
        QString key;
        int modelRow = -1;
        QLabel *label = nullptr;
        QLabel *device = nullptr;
        QWidget *editor = nullptr;
        QLabel *unit = nullptr;
        QLabel *storage = nullptr; // "EEPROM" where the value survives power-off
        QLabel *state = nullptr;
        bool typing = false; // the user typed since the editor last showed a model value
    };

    void rebuild();
    QWidget *createEditor(const model::Definition &definition);
    void editorChanged(const QString &key);
    void editorFinished(const QString &key);
    void refreshRow(const QString &key);
    void updateRow(Row &row);
    void showValue(Row &row, qint64 raw);
    void showUnread(Row &row);
    void updateButtons();
    void revertAll();
    Row *findRow(const QString &key);
    const Row *findRow(const QString &key) const;

    model::ParameterModel *m_model = nullptr;
    Options m_options;
    QWidget *m_form = nullptr; // the group boxes, rebuilt with the definitions
    QVBoxLayout *m_formLayout = nullptr;
    QVector<Row> m_rows;
    QString m_committing; // the key whose editor is sending its value to the model right now
    QHash<QString, int> m_rowIndex;
    QPushButton *m_read = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_revert = nullptr;
    QPushButton *m_saveProfile = nullptr;
    QPushButton *m_loadProfile = nullptr;
    QLabel *m_busyLabel = nullptr;
    QProgressBar *m_progress = nullptr;
    bool m_linkReady = false;
    bool m_busy = false;
};
