// The Health page's Settings section: the settings check of every servo found, against a robot
// template if one is chosen, one row per finding with its Fix, and Fix all; each fix shown
// verified or why not.
#pragma once

#include "robottemplate.h"
#include "settingscheck.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace feetech {
class BusClient;
}

class SettingsCheckPanel : public QWidget
{
    Q_OBJECT

public:
    enum Column {
        IdColumn,
        SettingColumn,
        ValueColumn,
        ExpectedColumn,
        WhyColumn,
        FixColumn, // a Fix button where a write fixes the finding
        ResultColumn, // "Fixed, verified" or why not, once fixed
        ColumnCount
    };

    explicit SettingsCheckPanel(feetech::BusClient *client, QWidget *parent = nullptr);

    // Reads the settings of every servo found; false and *error (also shown) when refused.
    bool check(QString *error = nullptr);
    // Fixes the finding of table row `row`, or every fixable one; false and *error (also
    // shown) when refused.
    bool fix(int row, QString *error = nullptr);
    bool fixAll(QString *error = nullptr);
    // Compares with template `name` (as RobotTemplate::name), or with none for an empty name.
    void chooseTemplate(const QString &name);

    // The findings of the last check, in the table's order.
    const QVector<feetech::SettingsFinding> &findings() const { return m_findings; }
    QTableWidget *table() const { return m_table; }
    QComboBox *templateBox() const { return m_template; }
    QPushButton *checkButton() const { return m_check; }
    QPushButton *fixAllButton() const { return m_fixAll; }
    QPushButton *fixButton(int row) const;
    QLabel *stateLabel() const { return m_state; }

signals:
    void message(const QString &message);

private:
    bool startFix(const QVector<feetech::SettingsFinding> &findings, QString *error);
    void showFindings(const QVector<feetech::SettingsFinding> &findings);
    void showOutcomes(const QVector<feetech::SettingsFixOutcome> &outcomes, const QString &text);
    void updateActions();
    void showState(const QString &text, bool error);
    feetech::SettingsExpectations expectations() const;

    feetech::BusClient *m_client = nullptr;
    QVector<feetech::RobotTemplate> m_templates;
    QVector<feetech::SettingsFinding> m_findings;
    QVector<bool> m_fixed; // per row: verified since the check

    QComboBox *m_template = nullptr;
    QPushButton *m_check = nullptr;
    QPushButton *m_fixAll = nullptr;
    QTableWidget *m_table = nullptr;
    QLabel *m_state = nullptr;
};
