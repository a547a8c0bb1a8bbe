// The bench cases: their titles, what each changes on the simulated bus and what it says then.
#include "benchcases.h"

#include "virtualfeetechbus.h"

QVector<BenchCases::Case> BenchCases::all()
{
    return {Case::CutPower,      Case::RestorePower, Case::BreakChainAfter,
            Case::MendChain,     Case::BlockHorn,    Case::FreeHorn,
            Case::Heat,          Case::StopHeating,  Case::LatchOverload,
            Case::SupplyTooHigh, Case::SupplyTooLow, Case::SupplyNormal};
}

QString BenchCases::title(Case benchCase)
{
    switch (benchCase) {
    case Case::CutPower:
        return tr("Cut the selected servo's power");
    case Case::RestorePower:
        return tr("Power the selected servo again");
    case Case::BreakChainAfter:
        return tr("Break the daisy chain after the selected servo");
    case Case::MendChain:
        return tr("Mend the daisy chain");
    case Case::BlockHorn:
        return tr("Block the selected servo's horn");
    case Case::FreeHorn:
        return tr("Free the selected servo's horn");
    case Case::Heat:
        return tr("Heat the selected servo (%1 °C/s)").arg(kHeatPerSecond);
    case Case::StopHeating:
        return tr("Stop heating the selected servo");
    case Case::LatchOverload:
        return tr("Latch an overload on the selected servo");
    case Case::SupplyTooHigh:
        return tr("Supply %1 V to the bus (too high for 7.4 V servos)")
            .arg(kHighSupplyVolts, 0, 'f', 1);
    case Case::SupplyTooLow:
        return tr("Supply %1 V to the bus (too low)").arg(kLowSupplyVolts, 0, 'f', 1);
    case Case::SupplyNormal:
        return tr("Supply each servo its usual voltage");
    }
    return {};
}

bool BenchCases::needsServo(Case benchCase)
{
    switch (benchCase) {
    case Case::MendChain:
    case Case::SupplyTooHigh:
    case Case::SupplyTooLow:
    case Case::SupplyNormal:
        return false;
    default:
        return true;
    }
}

bool BenchCases::play(Case benchCase, sim::VirtualFeetechBus &bus, int index)
{
    const auto supply =
        [&bus](const std::function<double(const sim::VirtualFeetechServo &)> &volts) {
            for (int servo = 0; servo < bus.servoCount(); ++servo)
                bus.servo(servo).setSupplyVoltage(volts(bus.servo(servo)));
            return true;
        };
    switch (benchCase) {
    case Case::CutPower:
        bus.setPowered(index, false);
        return true;
    case Case::RestorePower:
        bus.setPowered(index, true);
        return true;
    case Case::BreakChainAfter:
        bus.setChainBreakAfter(index);
        return true;
    case Case::MendChain:
        return bus.setChainBreakAfter(-1);
    case Case::BlockHorn:
        bus.servo(index).setExternalLoad(1000);
        return true;
    case Case::FreeHorn:
        bus.servo(index).setExternalLoad(0);
        return true;
    case Case::Heat:
        bus.servo(index).setTemperatureRise(kHeatPerSecond);
        return true;
    case Case::StopHeating:
        bus.servo(index).setTemperatureRise(0.0);
        return true;
    case Case::LatchOverload:
        bus.servo(index).setOverloadLatched(true);
        return true;
    case Case::SupplyTooHigh:
        return supply([](const sim::VirtualFeetechServo &) { return kHighSupplyVolts; });
    case Case::SupplyTooLow:
        return supply([](const sim::VirtualFeetechServo &) { return kLowSupplyVolts; });
    case Case::SupplyNormal:
        return supply([](const sim::VirtualFeetechServo &servo) {
            return servo.family() == feetech::Family::Hls
                ? sim::VirtualFeetechServo::kDefaultHlsSupplyVolts
                : sim::VirtualFeetechServo::kDefaultSupplyVolts;
        });
    }
    return false;
}

QString BenchCases::outcome(Case benchCase, int index)
{
    switch (benchCase) {
    case Case::CutPower:
        return tr("Servo #%1 has no power: it hears and answers nothing.").arg(index + 1);
    case Case::RestorePower:
        return tr("Servo #%1 has power again.").arg(index + 1);
    case Case::BreakChainAfter:
        return tr("The daisy chain is broken after servo #%1: the servos after it have neither "
                  "signal nor power.")
            .arg(index + 1);
    case Case::MendChain:
        return tr("The daisy chain is whole again.");
    case Case::BlockHorn:
        return tr("Servo #%1's horn is blocked: driven, its load rises and it stays put.")
            .arg(index + 1);
    case Case::FreeHorn:
        return tr("Servo #%1's horn is free.").arg(index + 1);
    case Case::Heat:
        return tr("Servo #%1 warms steadily until it trips at its maximum temperature.")
            .arg(index + 1);
    case Case::StopHeating:
        return tr("Servo #%1 is no longer heated: it cools toward the room's temperature.")
            .arg(index + 1);
    case Case::LatchOverload:
        return tr("Servo #%1's overload is latched: its torque is gone until the bus is "
                  "power-cycled.")
            .arg(index + 1);
    case Case::SupplyTooHigh:
        return tr("The bus has a %1 V supply.").arg(kHighSupplyVolts, 0, 'f', 1);
    case Case::SupplyTooLow:
        return tr("The bus has a %1 V supply.").arg(kLowSupplyVolts, 0, 'f', 1);
    case Case::SupplyNormal:
        return tr("Every servo has its usual supply again.");
    }
    return {};
}
