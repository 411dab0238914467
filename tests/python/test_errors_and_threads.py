"""Bad input raises onetip exceptions with a message naming it; callbacks that
raise, stop() while a callback runs and dropping a running sensor never hang."""
import threading

import pytest

import onetip
from conftest import write_scenario


def test_bad_paths_raise_input_errors_naming_them(tmp_path, press_scenario):
    missing = tmp_path / "missing.yaml"
    with pytest.raises(onetip.InputError, match="missing.yaml"):
        onetip.Sensor(f"sim:{missing}")
    with pytest.raises(onetip.InputError, match="missing.yaml"):
        onetip.Sensor(f"sim:{press_scenario}", calibration=str(missing), pattern=str(missing))
    with pytest.raises(onetip.InputError, match="nowhere"):
        onetip.Sensor(str(tmp_path / "nowhere"), calibration=str(missing), pattern=str(missing))
    with pytest.raises(onetip.InputError, match="missing.yaml"):
        onetip.SimulatedSensor(str(missing))
    with pytest.raises(onetip.InputError, match="missing.yaml"):
        onetip.SensorOptions.load(str(missing))
    assert issubclass(onetip.InputError, onetip.Error) and issubclass(onetip.Error, RuntimeError)


def test_bad_options_name_the_field(press_scenario):
    with pytest.raises(onetip.InputError, match="queue_capacity"):
        onetip.SensorOptions(queue_capacity=0).validate()
    with pytest.raises(onetip.InputError, match="release_mm"):
        onetip.Sensor(f"sim:{press_scenario}", options=onetip.SensorOptions(press_mm=1.0, release_mm=2.0))
    with pytest.raises(AttributeError):
        onetip.SensorOptions(no_such_field=1)


def test_bad_options_are_refused_at_construction():
    with pytest.raises(onetip.InputError, match="queue_capacity"):
        onetip.SensorOptions(queue_capacity=-3)
    with pytest.raises(onetip.InputError, match="beta"):
        onetip.SensorOptions(filter_beta=float("nan"))


def test_paths_may_be_pathlib_paths(tmp_path, press_scenario):
    import pathlib
    scenario = pathlib.Path(press_scenario)
    options = onetip.SensorOptions(queue_capacity=5)
    options.save(tmp_path / "options.yaml")
    assert onetip.SensorOptions.load(tmp_path / "options.yaml").queue_capacity == 5
    simulated = onetip.SimulatedSensor(scenario, render=False, frames=2)
    simulated.save_calibration(tmp_path / "calib.yaml", tmp_path / "pattern.yaml")
    assert (tmp_path / "calib.yaml").is_file() and (tmp_path / "pattern.yaml").is_file()
    with onetip.Sensor(pathlib.Path(f"sim:{scenario}"), calibration=tmp_path / "calib.yaml",
                       pattern=tmp_path / "pattern.yaml") as sensor:
        assert sensor.source == f"sim:{scenario}"


def test_options_round_trip_through_yaml(tmp_path):
    options = onetip.SensorOptions(lossless=True, queue_capacity=7, gain=[1, 2, 3, 4, 5, 6],
                                   filter=onetip.FilterKind.one_euro, press_mm=2.5)
    options.save(str(tmp_path / "options.yaml"))
    loaded = onetip.SensorOptions.load(str(tmp_path / "options.yaml"))
    assert (loaded.lossless, loaded.queue_capacity, loaded.gain, loaded.filter, loaded.press_mm) == (
        True, 7, [1, 2, 3, 4, 5, 6], onetip.FilterKind.one_euro, 2.5)
    assert loaded.release_mm == onetip.SensorOptions().release_mm


def test_start_twice_is_a_state_error(tmp_path):
    with onetip.Sensor(f"sim:{write_scenario(tmp_path, 0.1)}") as sensor:
        sensor.start()
        with pytest.raises(onetip.StateError):
            sensor.start()


def test_a_raising_callback_becomes_an_error_event_and_the_sensor_goes_on(tmp_path):
    options = onetip.SensorOptions(lossless=True)
    with onetip.Sensor(f"sim:{write_scenario(tmp_path, 0.2)}", options=options) as sensor:
        def explode(frame):
            raise ValueError(f"boom at frame {frame.frame}")
        sensor.on_frame(explode)
        sensor.start()
        assert sensor.wait_finished(60.0)
        errors = []
        while (event := sensor.poll_event()) is not None:
            errors.append(event)
        stats = sensor.stats()
    assert stats.frames_processed == 7 and stats.callback_errors == 7
    assert len(errors) == 7 and all(e.type == onetip.EventType.error for e in errors)
    assert "ValueError: boom at frame 0" in errors[0].message


def test_stop_and_drop_while_a_callback_holds_the_gil_do_not_deadlock(tmp_path):
    scenario = write_scenario(tmp_path, 30.0)  # long: only stop() ends it
    for finish in ("stop", "drop"):
        entered = threading.Event()
        calls = []

        def slow(frame):
            calls.append(frame.frame)
            entered.set()
            threading.Event().wait(0.05)  # holds the GIL's turn on the processing thread

        sensor = onetip.Sensor(f"sim:{scenario}", options=onetip.SensorOptions(lossless=True))
        sensor.on_frame(slow)
        sensor.start()
        assert entered.wait(30.0)
        if finish == "stop":
            sensor.stop()
            assert not sensor.running
            seen = len(calls)
            threading.Event().wait(0.2)
            assert len(calls) == seen  # no callback after stop() returned
        del sensor  # the destructor stops a running sensor without deadlocking


def test_wait_event_on_a_sensor_never_started_returns_none(tmp_path):
    sensor = onetip.Sensor(f"sim:{write_scenario(tmp_path, 0.1)}")
    assert sensor.wait_event(0.05) is None and sensor.poll_event() is None and sensor.poll_frame() is None
