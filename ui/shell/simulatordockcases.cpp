// The Simulator dock's bench cases: what goes wrong on a real bench (a servo without power, a
// broken daisy chain, a supply out of range, heat, a blocked horn, a latched overload), played on
// the simulated bus so the Doctor, the health check and the guard can be seen at work.
#include "simulatordock.h"

#include "simulator.h"
#include "widgethelpers.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

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
    const auto add = [this](const QString &text, BenchCase benchCase) {
        m_benchCase->addItem(text, int(benchCase));
    };
    add(tr("Cut the selected servo's power"), BenchCase::CutPower);
    add(tr("Power the selected servo again"), BenchCase::RestorePower);
    add(tr("Break the daisy chain after the selected servo"), BenchCase::BreakChainAfter);
    add(tr("Mend the daisy chain"), BenchCase::MendChain);
    add(tr("Block the selected servo's horn"), BenchCase::BlockHorn);
    add(tr("Free the selected servo's horn"), BenchCase::FreeHorn);
    add(tr("Heat the selected servo (%1 °C/s)").arg(kHeatPerSecond), BenchCase::Heat);
    add(tr("Stop heating the selected servo"), BenchCase::StopHeating);
    add(tr("Latch an overload on the selected servo"), BenchCase::LatchOverload);
    add(tr("Supply %1 V to the bus (too high for 7.4 V servos)").arg(kHighSupplyVolts, 0, 'f', 1),
        BenchCase::SupplyTooHigh);
    add(tr("Supply %1 V to the bus (too low)").arg(kLowSupplyVolts, 0, 'f', 1),
        BenchCase::SupplyTooLow);
    add(tr("Supply each servo its usual voltage"), BenchCase::SupplyNormal);
    row->addWidget(m_benchCase, 1);
    auto *play = widgethelpers::actionButton(tr("Play"), "playBenchCaseButton",
                                             tr("Plays the chosen bench case now"), box);
    connect(play, &QPushButton::clicked, this,
            [this] { playBenchCase(BenchCase(m_benchCase->currentData().toInt())); });
    row->addWidget(play);
    return box;
}

bool SimulatorDock::playBenchCase(BenchCase benchCase)
{
    using sim::VirtualFeetechBus;
    const auto onServo = [this](const std::function<void(VirtualFeetechBus &, int)> &change,
                                const char *done) {
        return onSelected(
            [&](VirtualFeetechBus &bus, int index, QString *) {
                change(bus, index);
                return true;
            },
            [done](int index) { return tr(done).arg(index + 1); });
    };
    const auto supply = [this](const std::function<double(const sim::VirtualFeetechServo &)> &volts,
                               const QString &done) {
        return onBus(
            [&](VirtualFeetechBus &bus, QString *) {
                for (int index = 0; index < bus.servoCount(); ++index)
                    bus.servo(index).setSupplyVoltage(volts(bus.servo(index)));
                return true;
            },
            done);
    };
    switch (benchCase) {
    case BenchCase::CutPower:
        return onServo([](VirtualFeetechBus &bus, int index) { bus.setPowered(index, false); },
                       QT_TR_NOOP("Servo #%1 has no power: it hears and answers nothing."));
    case BenchCase::RestorePower:
        return onServo([](VirtualFeetechBus &bus, int index) { bus.setPowered(index, true); },
                       QT_TR_NOOP("Servo #%1 has power again."));
    case BenchCase::BreakChainAfter:
        return onServo([](VirtualFeetechBus &bus, int index) { bus.setChainBreakAfter(index); },
                       QT_TR_NOOP("The daisy chain is broken after servo #%1: the servos after "
                                  "it have neither signal nor power."));
    case BenchCase::MendChain:
        return onBus([](VirtualFeetechBus &bus, QString *) { return bus.setChainBreakAfter(-1); },
                     tr("The daisy chain is whole again."));
    case BenchCase::BlockHorn:
        return onServo(
            [](VirtualFeetechBus &bus, int index) { bus.servo(index).setExternalLoad(1000); },
            QT_TR_NOOP("Servo #%1's horn is blocked: driven, its load rises and it stays put."));
    case BenchCase::FreeHorn:
        return onServo(
            [](VirtualFeetechBus &bus, int index) { bus.servo(index).setExternalLoad(0); },
            QT_TR_NOOP("Servo #%1's horn is free."));
    case BenchCase::Heat:
        return onServo(
            [](VirtualFeetechBus &bus, int index) {
                bus.servo(index).setTemperatureRise(kHeatPerSecond);
            },
            QT_TR_NOOP("Servo #%1 warms steadily until it trips at its maximum temperature."));
    case BenchCase::StopHeating:
        return onServo(
            [](VirtualFeetechBus &bus, int index) { bus.servo(index).setTemperatureRise(0.0); },
            QT_TR_NOOP("Servo #%1 is no longer heated: it cools toward the room's temperature."));
    case BenchCase::LatchOverload:
        return onServo(
            [](VirtualFeetechBus &bus, int index) { bus.servo(index).setOverloadLatched(true); },
            QT_TR_NOOP("Servo #%1's overload is latched: its torque is gone until the bus is "
                       "power-cycled."));
    case BenchCase::SupplyTooHigh:
        return supply([](const sim::VirtualFeetechServo &) { return kHighSupplyVolts; },
                      tr("The bus has a %1 V supply.").arg(kHighSupplyVolts, 0, 'f', 1));
    case BenchCase::SupplyTooLow:
        return supply([](const sim::VirtualFeetechServo &) { return kLowSupplyVolts; },
                      tr("The bus has a %1 V supply.").arg(kLowSupplyVolts, 0, 'f', 1));
    case BenchCase::SupplyNormal:
        return supply(
            [](const sim::VirtualFeetechServo &servo) {
                return servo.family() == feetech::Family::Hls
                    ? sim::VirtualFeetechServo::kDefaultHlsSupplyVolts
                    : sim::VirtualFeetechServo::kDefaultSupplyVolts;
            },
            tr("Every servo has its usual supply again."));
    }
    return false;
}
