// The Simulator dock: a table of the simulated servos refreshed a few times a second, the hand's
// slider and sweep, and the bus buttons, all through SimulatorThread::call.
#include "simulatordock.h"

#include "modeltable.h"
#include "registertable.h"
#include "simulatorthread.h"
#include "widgethelpers.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace {

enum ServoColumn {
    PlaceColumn,
    IdColumn,
    RateColumn,
    ModelColumn,
    PositionColumn,
    TorqueColumn,
    ConditionColumn,
    ColumnCount
};

} // namespace

SimulatorDock::SimulatorDock(QWidget *parent)
    : QDockWidget(tr("Simulator"), parent)
{
    setObjectName(QStringLiteral("simulatorDock"));
    setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea | Qt::RightDockWidgetArea);

    auto *content = new QWidget(this);
    auto *layout = new QHBoxLayout(content);
    layout->setContentsMargins(4, 4, 4, 4);

    m_table = new QTableWidget(0, ColumnCount, content);
    m_table->setObjectName(QStringLiteral("simulatedServos"));
    m_table->setHorizontalHeaderLabels(
        {tr("#"), tr("ID"), tr("Rate"), tr("Model"), tr("Position"), tr("Torque"), tr("Bench")});
    m_table->verticalHeader()->hide();
    // Compact rows: an arm's six joints fit in the dock's starting height at 1366x768.
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setToolTip(tr("The servos on the simulated bus, as they are now"));
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &SimulatorDock::updateSelection);
    // As tall as the controls beside it, never taller: once a note wraps, the scroll area sizes
    // the dock's content by its preferred height, and the table's would make it scroll.
    m_table->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
    layout->addWidget(m_table, 3);

    auto *controls = new QVBoxLayout;
    controls->addWidget(buildHandControls());
    controls->addWidget(buildBusButtons());
    controls->addWidget(buildBenchCases());
    m_note = new QLabel(content);
    m_note->setObjectName(QStringLiteral("simulatorNote"));
    m_note->setWordWrap(true);
    m_note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // A line kept for it from the start, measured on a note in the language shown (a Chinese
    // line is taller than a Latin one): the dock's starting height has room for the first note,
    // which then shows without a scroll bar.
    m_note->setText(tr("Power-cycled the simulated bus."));
    m_note->setMinimumHeight(m_note->sizeHint().height());
    m_note->clear();
    controls->addWidget(m_note);
    controls->addStretch();
    layout->addLayout(controls, 4);
    // On a 1366x768 screen the pages above need most of the height: the dock may be shorter than
    // its controls and scrolls them, rather than push the window's status bar off the screen.
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    setWidget(scroll);

    m_refreshTimer = new QTimer(this);
    m_refreshTimer->setInterval(kRefreshMs);
    connect(m_refreshTimer, &QTimer::timeout, this, [this] {
        if (isVisible())
            refresh();
    });
    updateSelection();
}

int SimulatorDock::startingHeight() const
{
    const auto *scroll = qobject_cast<const QScrollArea *>(widget());
    return minimumSizeHint().height() - scroll->minimumSizeHint().height()
        + scroll->widget()->minimumSizeHint().height();
}

SimulatorDock::~SimulatorDock()
{
    disconnect(m_handNotes);
}

QWidget *SimulatorDock::buildHandControls()
{
    auto *box = new QWidget(this);
    auto *grid = new QGridLayout(box);
    grid->setContentsMargins(0, 0, 0, 0);

    grid->addWidget(new QLabel(tr("Horn"), box), 0, 0);
    m_horn = new QSlider(Qt::Horizontal, box);
    m_horn->setObjectName(QStringLiteral("hornSlider"));
    m_horn->setRange(0, 4095);
    connect(m_horn, &QSlider::valueChanged, this, [this](int position) {
        m_hornValue->setNum(position);
        if (!m_updating)
            turnSelected(position);
    });
    grid->addWidget(m_horn, 0, 1, 1, 6);
    m_hornValue = new QLabel(box);
    m_hornValue->setMinimumWidth(
        m_hornValue->fontMetrics().horizontalAdvance(QStringLiteral("0000")));
    grid->addWidget(m_hornValue, 0, 7);

    grid->addWidget(new QLabel(tr("Sweep"), box), 1, 0);
    const auto positionSpin = [box](int value, const char *name, const QString &tip) {
        auto *spin = new QSpinBox(box);
        spin->setObjectName(QLatin1String(name));
        spin->setRange(0, 4095);
        spin->setValue(value);
        spin->setToolTip(tip);
        return spin;
    };
    m_sweepFrom = positionSpin(1024, "sweepFrom", tr("Where the hand starts, and comes back to"));
    m_sweepTo = positionSpin(3072, "sweepTo", tr("Where the hand turns back"));
    m_sweepSeconds = new QDoubleSpinBox(box);
    m_sweepSeconds->setObjectName(QStringLiteral("sweepSeconds"));
    m_sweepSeconds->setRange(0.1, sim::Hand::kMaxSweepSeconds);
    m_sweepSeconds->setValue(4.0);
    m_sweepSeconds->setSuffix(tr(" s"));
    m_sweepSeconds->setToolTip(tr("How long one sweep there and back takes"));
    m_sweepCycles = new QSpinBox(box);
    m_sweepCycles->setObjectName(QStringLiteral("sweepCycles"));
    m_sweepCycles->setRange(0, sim::Hand::kMaxSweepCycles);
    m_sweepCycles->setSpecialValueText(tr("until let go"));
    m_sweepCycles->setSuffix(tr("×"));
    m_sweepCycles->setToolTip(tr("How many times; 0 sweeps until Let go"));
    grid->addWidget(m_sweepFrom, 1, 1);
    grid->addWidget(new QLabel(tr("to"), box), 1, 2);
    grid->addWidget(m_sweepTo, 1, 3);
    grid->addWidget(m_sweepSeconds, 1, 4);
    grid->addWidget(m_sweepCycles, 1, 5);
    m_sweep = widgethelpers::actionButton(
        tr("Sweep"), "sweepButton",
        tr("The hand sweeps the selected joint from the first position to the second and back"),
        box);
    connect(m_sweep, &QPushButton::clicked, this, [this] {
        sweepSelected(m_sweepFrom->value(), m_sweepTo->value(), m_sweepSeconds->value(),
                      m_sweepCycles->value());
    });
    grid->addWidget(m_sweep, 1, 6);
    m_letGo = widgethelpers::actionButton(tr("Let go"), "letGoButton",
                                          tr("The hand stops every sweep"), box);
    connect(m_letGo, &QPushButton::clicked, this, &SimulatorDock::letGo);
    grid->addWidget(m_letGo, 1, 7);
    return box;
}

QWidget *SimulatorDock::buildBusButtons()
{
    auto *box = new QWidget(this);
    auto *row = new QHBoxLayout(box);
    row->setContentsMargins(0, 0, 0, 0);
    auto *plug = widgethelpers::actionButton(
        tr("Plug in a factory-new servo…"), "plugButton",
        tr("Adds a servo as it comes from the factory: ID 1, its family's default rate"), box);
    connect(plug, &QPushButton::clicked, this, &SimulatorDock::choosePlug);
    m_unplug = widgethelpers::actionButton(tr("Unplug"), "unplugButton",
                                           tr("Takes the selected servo off the bus"), box);
    connect(m_unplug, &QPushButton::clicked, this, &SimulatorDock::unplugSelected);
    m_plugBack = widgethelpers::actionButton(
        tr("Plug back in"), "plugBackButton",
        tr("Puts the servo unplugged last back on the bus, as it was"), box);
    m_plugBack->setEnabled(false);
    connect(m_plugBack, &QPushButton::clicked, this, &SimulatorDock::plugBackIn);
    m_putAtId = widgethelpers::actionButton(
        tr("Put at ID…"), "putAtIdButton",
        tr("Changes the selected servo's ID in its EEPROM, as a set-up would; two servos may "
           "then share one"),
        box);
    connect(m_putAtId, &QPushButton::clicked, this, &SimulatorDock::chooseId);
    auto *cycle = widgethelpers::actionButton(
        tr("Power-cycle"), "powerCycleButton",
        tr("Switches the bus off and on: torque off, RAM back to its power-on values"), box);
    connect(cycle, &QPushButton::clicked, this, &SimulatorDock::powerCycle);
    for (QPushButton *button : {plug, m_unplug, m_plugBack, m_putAtId, cycle})
        row->addWidget(button);
    row->addStretch();
    return box;
}

QWidget *SimulatorDock::buildBenchCases()
{
    auto *box = new QWidget(this);
    auto *row = new QHBoxLayout(box);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(new QLabel(tr("Bench case"), box));
    m_benchCase = new QComboBox(box);
    m_benchCase->setObjectName(QStringLiteral("benchCase"));
    m_benchCase->setToolTip(tr("What goes wrong on a real bench, played on the selected servo or "
                               "on the whole bus"));
    for (const BenchCases::Case benchCase : BenchCases::all())
        m_benchCase->addItem(BenchCases::title(benchCase), int(benchCase));
    row->addWidget(m_benchCase, 1);
    auto *play = widgethelpers::actionButton(tr("Play"), "playBenchCaseButton",
                                             tr("Plays the chosen bench case now"), box);
    connect(play, &QPushButton::clicked, this,
            [this] { playBenchCase(BenchCases::Case(m_benchCase->currentData().toInt())); });
    row->addWidget(play);
    return box;
}

QStringList SimulatorDock::simulatedModels()
{
    // The model table lists a name once per model number (SM30BL has twenty): the simulator
    // plugs a servo by name, so each name is offered once.
    QStringList names;
    for (const feetech::ModelInfo &model : feetech::ModelTable::builtIn().models()) {
        if (!names.contains(model.name) && sim::VirtualFeetechBus::resolveModel(model.name))
            names.append(model.name);
    }
    return names;
}

void SimulatorDock::setSimulator(sim::SimulatorThread *simulator)
{
    disconnect(m_handNotes);
    m_simulator = simulator;
    m_servos.clear();
    if (m_simulator) {
        m_simulator->call([this](sim::Simulator &running) {
            // Queued to the GUI thread: the note comes from the simulator's.
            m_handNotes = connect(&running, &sim::Simulator::handNote, this,
                                  [this](const QString &text) { showNote(text, false); });
        });
        m_refreshTimer->start();
    } else {
        m_refreshTimer->stop();
    }
    refresh();
}

bool SimulatorDock::onBus(const BusWork &work, const QString &done)
{
    QString problem = tr("No simulated Feetech bus is running.");
    if (m_simulator) {
        m_simulator->call([&](sim::Simulator &simulator) {
            simulator.advanceNow();
            if (sim::VirtualFeetechBus *bus = simulator.feetechBus()) {
                problem.clear();
                sim::SimRefusal why;
                if (!work(*bus, &why))
                    problem = why ? why.describe() : tr("The simulator refused.");
            }
        });
    }
    showNote(problem.isEmpty() ? done : problem, !problem.isEmpty());
    refresh();
    return problem.isEmpty();
}

bool SimulatorDock::onSelected(
    const std::function<bool(sim::VirtualFeetechBus &, int, sim::SimRefusal *)> &work,
    const std::function<QString(int)> &done)
{
    const int index = selectedIndex();
    if (index < 0) {
        showNote(tr("Select a servo in the list first."), true);
        return false;
    }
    return onBus(
        [&](sim::VirtualFeetechBus &bus, sim::SimRefusal *why) { return work(bus, index, why); },
        done(index));
}

void SimulatorDock::showNote(const QString &text, bool problem)
{
    m_note->setText(text);
    m_note->setStyleSheet(problem ? QStringLiteral("color: #b3261e;") : QString());
    emit message(text);
}

QString SimulatorDock::note() const
{
    return m_note->text();
}

void SimulatorDock::refresh()
{
    QVector<sim::SimulatedServo> servos;
    QString lastUnplugged;
    if (m_simulator) {
        m_simulator->call([&servos, &lastUnplugged](sim::Simulator &simulator) {
            simulator.advanceNow();
            if (sim::VirtualFeetechBus *bus = simulator.feetechBus()) {
                servos = sim::simulatedServos(*bus);
                if (bus->unpluggedCount() > 0) {
                    const sim::VirtualFeetechServo &off =
                        bus->unpluggedServo(bus->unpluggedCount() - 1);
                    lastUnplugged = tr("ID %1 (%2)").arg(off.id()).arg(off.model().name);
                }
            }
        });
    }
    m_lastUnplugged = lastUnplugged;
    m_plugBack->setEnabled(!lastUnplugged.isEmpty());
    m_plugBack->setToolTip(
        lastUnplugged.isEmpty()
            ? tr("Nothing was unplugged")
            : tr("Puts %1, unplugged last, back on the bus as it was").arg(lastUnplugged));
    const int selected = selectedIndex();
    m_servos = servos;
    const QSignalBlocker quiet(m_table);
    m_table->setRowCount(int(servos.size()));
    for (int row = 0; row < servos.size(); ++row) {
        const sim::SimulatedServo &servo = servos.at(row);
        const QStringList cells {
            QStringLiteral("#%1").arg(servo.index + 1),
            QString::number(servo.id),
            QString::number(servo.baud),
            servo.model,
            QString::number(servo.position),
            servo.torqueOn       ? tr("on")
                : servo.sweeping ? tr("off, hand sweeping")
                                 : tr("off"),
            tr("%1 V, %2 °C").arg(servo.supplyVolts, 0, 'f', 1).arg(servo.temperature)
                + (sim::benchCondition(servo).isEmpty()
                       ? QString()
                       : QStringLiteral(", ") + sim::benchCondition(servo))};
        for (int column = 0; column < cells.size(); ++column) {
            QTableWidgetItem *item = m_table->item(row, column);
            if (!item) {
                item = new QTableWidgetItem;
                m_table->setItem(row, column, item);
            }
            item->setText(cells.at(column));
        }
    }
    if (selected >= 0 && selected < servos.size())
        m_table->selectRow(selected);
    else if (!servos.isEmpty() && selected < 0)
        m_table->selectRow(0);
    updateSelection();
}

void SimulatorDock::selectServo(int index)
{
    m_table->selectRow(index);
    updateSelection();
}

int SimulatorDock::selectedIndex() const
{
    const QList<QTableWidgetItem *> items = m_table->selectedItems();
    return items.isEmpty() ? -1 : items.first()->row();
}

void SimulatorDock::updateSelection()
{
    const int index = selectedIndex();
    const bool chosen = index >= 0 && index < m_servos.size();
    m_unplug->setEnabled(chosen);
    m_putAtId->setEnabled(chosen);
    m_letGo->setEnabled(
        std::any_of(m_servos.cbegin(), m_servos.cend(),
                    [](const sim::SimulatedServo &servo) { return servo.sweeping; }));
    if (!chosen) {
        m_horn->setEnabled(false);
        m_sweep->setEnabled(false);
        m_horn->setToolTip(tr("Select a servo to turn its horn by hand"));
        return;
    }
    const sim::SimulatedServo &servo = m_servos.at(index);
    const QString tip = servo.torqueOn
        ? tr("Servo #%1 has its torque on: it holds its position against the hand. Switch its "
             "torque off to turn it.")
              .arg(index + 1)
        : tr("Turns servo #%1's horn by hand, as during a calibration").arg(index + 1);
    m_horn->setEnabled(!servo.torqueOn);
    m_horn->setToolTip(tip);
    m_sweep->setEnabled(!servo.torqueOn);
    m_sweep->setToolTip(tip);
    if (!m_horn->isSliderDown()) {
        m_updating = true;
        m_horn->setRange(0, servo.maxPosition);
        m_horn->setValue(servo.position);
        m_hornValue->setNum(servo.position);
        m_updating = false;
    }
}

bool SimulatorDock::turnSelected(int position)
{
    return onSelected(
        [position](sim::VirtualFeetechBus &bus, int index, sim::SimRefusal *why) {
            return bus.hand().turnServo(index, position, why);
        },
        [this, position](int index) {
            return tr("Turned servo #%1 to %2.").arg(index + 1).arg(position);
        });
}

bool SimulatorDock::sweepSelected(int from, int to, double seconds, int cycles)
{
    return onSelected(
        [=](sim::VirtualFeetechBus &bus, int index, sim::SimRefusal *why) {
            return bus.hand().sweepServoFromHere(index, from, to, seconds, cycles,
                                                 sim::Hand::Way::Direct, why);
        },
        [=](int index) {
            return tr("The hand sweeps servo #%1 from %2 to %3 and back every %4 s.")
                .arg(index + 1)
                .arg(from)
                .arg(to)
                .arg(seconds);
        });
}

bool SimulatorDock::playBenchCase(BenchCases::Case benchCase)
{
    if (!BenchCases::needsServo(benchCase)) {
        return onBus(
            [benchCase](sim::VirtualFeetechBus &bus, sim::SimRefusal *) {
                return BenchCases::play(benchCase, bus, -1);
            },
            BenchCases::outcome(benchCase, -1));
    }
    return onSelected(
        [benchCase](sim::VirtualFeetechBus &bus, int index, sim::SimRefusal *) {
            return BenchCases::play(benchCase, bus, index);
        },
        [benchCase](int index) { return BenchCases::outcome(benchCase, index); });
}

bool SimulatorDock::letGo()
{
    return onBus(
        [](sim::VirtualFeetechBus &bus, sim::SimRefusal *) {
            bus.hand().stop();
            return true;
        },
        tr("The hand let go."));
}

bool SimulatorDock::plugFactoryNew(const QString &model)
{
    return onBus(
        [&model](sim::VirtualFeetechBus &bus, sim::SimRefusal *why) {
            return bus.plug({1, model, 0}, why);
        },
        tr("Plugged in a factory-new %1 at ID 1.").arg(model));
}

bool SimulatorDock::unplugSelected()
{
    return onSelected(
        [](sim::VirtualFeetechBus &bus, int index, sim::SimRefusal *) { return bus.unplug(index); },
        [this](int index) { return tr("Unplugged servo #%1.").arg(index + 1); });
}

bool SimulatorDock::plugBackIn()
{
    return onBus([](sim::VirtualFeetechBus &bus, sim::SimRefusal *) { return bus.plugBack(); },
                 tr("Plugged %1 back in.").arg(m_lastUnplugged));
}

bool SimulatorDock::putSelectedAtId(int id)
{
    return onSelected(
        [id](sim::VirtualFeetechBus &bus, int index, sim::SimRefusal *why) {
            return bus.setServoId(index, id, why);
        },
        [this, id](int index) { return tr("Servo #%1 is now at ID %2.").arg(index + 1).arg(id); });
}

bool SimulatorDock::powerCycle()
{
    return onBus(
        [](sim::VirtualFeetechBus &bus, sim::SimRefusal *) {
            bus.powerCycle();
            return true;
        },
        tr("Power-cycled the simulated bus."));
}

void SimulatorDock::choosePlug()
{
    const QStringList models = simulatedModels();
    bool chosen = false;
    const QString model = QInputDialog::getItem(
        this, tr("Plug in a factory-new servo"),
        tr("Model (it comes at ID 1, at its family's default rate):"), models,
        std::max(0, int(models.indexOf(QStringLiteral("STS3215")))), false, &chosen);
    if (chosen)
        plugFactoryNew(model);
}

void SimulatorDock::chooseId()
{
    const int index = selectedIndex();
    if (index < 0 || index >= m_servos.size())
        return;
    bool chosen = false;
    const int id = QInputDialog::getInt(
        this, tr("Put at ID"),
        tr("New ID for servo #%1 (another servo may have it too):").arg(index + 1),
        m_servos.at(index).id, 0, feetech::kMaxServoId, 1, &chosen);
    if (chosen)
        putSelectedAtId(id);
}
