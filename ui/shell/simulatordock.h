// The Simulator dock of the demo: the simulated Feetech servos, a hand to turn and sweep their
// horns, plugging, unplugging, re-addressing and power-cycling them, and the bench cases to play.
#pragma once

#include "benchcases.h"
#include "simcommands.h"

#include <QDockWidget>
#include <QMetaObject>

#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace sim {
class SimRefusal;
class SimulatorThread;
class VirtualFeetechBus;
} // namespace sim

class SimulatorDock : public QDockWidget
{
    Q_OBJECT

public:
    static constexpr int kRefreshMs = 250;

    explicit SimulatorDock(QWidget *parent = nullptr);
    ~SimulatorDock() override;

    // The simulated Feetech bus shown (null: none). Every look and change goes through
    // SimulatorThread::call, never to the simulator directly.
    void setSimulator(sim::SimulatorThread *simulator);
    sim::SimulatorThread *simulator() const { return m_simulator; }

    // The height that shows every control without scrolling, title included: the dock starts
    // there where the window has room (it scrolls its controls where it has not).
    int startingHeight() const;

    // What the buttons do, after their dialogs; each says how it went in the dock's note and
    // returns whether it worked.
    bool turnSelected(int position);
    bool sweepSelected(int from, int to, double seconds, int cycles);
    bool letGo();
    bool plugFactoryNew(const QString &model); // at ID 1, the family's default rate
    bool unplugSelected();
    // The servo unplugged last, back on the bus as it was (its ID, rate and settings).
    bool plugBackIn();
    bool putSelectedAtId(int id);
    bool powerCycle();

    // Plays a bench case on the selected servo or the whole bus.
    bool playBenchCase(BenchCases::Case benchCase);
    QComboBox *benchCaseChoice() const { return m_benchCase; }

    void refresh(); // reads the servo list now (a timer does it while the dock is shown)
    void selectServo(int index);
    int selectedIndex() const; // -1: none
    const QVector<sim::SimulatedServo> &servos() const { return m_servos; }
    QTableWidget *table() const { return m_table; }
    QSlider *hornSlider() const { return m_horn; }
    QString note() const;

    // The models the plug dialog offers: every model the simulator can play.
    static QStringList simulatedModels();

signals:
    void message(const QString &text);

private:
    QWidget *buildHandControls();
    QWidget *buildBusButtons();
    QWidget *buildBenchCases();
    // Runs `work` on the bus in the simulator's thread and notes how it went: `done`, or the
    // error it gave; false without a bus.
    using BusWork = std::function<bool(sim::VirtualFeetechBus &, sim::SimRefusal *why)>;
    bool onBus(const BusWork &work, const QString &done);
    // The same on the selected servo, whose index `work` and `done` get; false and a note when
    // none is selected.
    bool
    onSelected(const std::function<bool(sim::VirtualFeetechBus &, int, sim::SimRefusal *)> &work,
               const std::function<QString(int)> &done);
    void showNote(const QString &text, bool problem);
    void updateSelection();
    void choosePlug();
    void chooseId();

    sim::SimulatorThread *m_simulator = nullptr;
    QMetaObject::Connection m_handNotes;
    QVector<sim::SimulatedServo> m_servos;
    QTableWidget *m_table = nullptr;
    QSlider *m_horn = nullptr;
    QLabel *m_hornValue = nullptr;
    QSpinBox *m_sweepFrom = nullptr;
    QSpinBox *m_sweepTo = nullptr;
    QDoubleSpinBox *m_sweepSeconds = nullptr;
    QSpinBox *m_sweepCycles = nullptr;
    QPushButton *m_sweep = nullptr;
    QPushButton *m_letGo = nullptr;
    QPushButton *m_unplug = nullptr;
    QPushButton *m_plugBack = nullptr;
    QString m_lastUnplugged; // "ID 3 (STS3215)", empty when none is off the bus
    QPushButton *m_putAtId = nullptr;
    QComboBox *m_benchCase = nullptr;
    QLabel *m_note = nullptr;
    QTimer *m_refreshTimer = nullptr;
    bool m_updating = false; // the list is being shown: slider moves are not the user's
};
