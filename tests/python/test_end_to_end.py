"""The simulated press through onetip.Sensor, compared frame by frame with
`onetip process` (the C++ pipeline) on the same scenario."""
import threading

import numpy as np

import onetip

TOL = 2e-6  # pose.csv and markers.csv carry 6 decimals


def test_contact_begins_and_ends_where_the_cpp_pipeline_says(press, cli_reference):
    contact = cli_reference.contact_frames()
    assert contact, "the reference saw no contact: the scenario or the CLI is broken"
    begins = press.of_type(onetip.EventType.contact_begin)
    ends = press.of_type(onetip.EventType.contact_end)
    assert [e.frame for e in begins] == [contact[0]]
    assert [e.frame for e in ends] == [contact[-1] + 1]
    # The shipped press stays inside the working range (dz in [0, 3] mm): a first run shows no error event.
    assert press.of_type(onetip.EventType.error) == []
    assert max(cli_reference.raw(f)[2] for f in contact) < onetip.SensorOptions().working_range[2]


def test_a_press_past_the_working_range_is_reported_where_it_leaves_the_range(press_scenario):
    """tests/data/scenarios/press_beyond_range.yaml presses to 5 mm: an error event "beyond the working range"
    at each frame where the measured input leaves the range, and nowhere else."""
    options = onetip.SensorOptions(lossless=True, event_queue_capacity=100000, frame_queue_capacity=1000)
    scenario = press_scenario.parents[2] / "tests" / "data" / "scenarios" / "press_beyond_range.yaml"
    events, frames = [], {}
    with onetip.Sensor(f"sim:{scenario}", options=options) as sensor:
        sensor.start()
        while (event := sensor.wait_event(5.0)) is not None:
            events.append(event)
        assert sensor.wait_finished(60.0)
        while (frame := sensor.poll_frame()) is not None:
            frames[frame.frame] = frame
    leaves = [f for f in sorted(frames)
              if frames[f].out_of_range and not (f - 1 in frames and frames[f - 1].out_of_range)]
    reported = [e.frame for e in events if e.type == onetip.EventType.error and "working range" in e.message]
    assert leaves, "the press never left the working range"
    assert reported == leaves
    assert all(frames[f].raw[2] > options.working_range[2] for f in leaves)  # it is the press depth that leaves


def test_every_input_event_matches_the_cpp_result_of_its_frame(press, cli_reference):
    inputs = press.of_type(onetip.EventType.input)
    assert [e.frame for e in inputs] == cli_reference.contact_frames()
    for e in inputs:
        assert e.input.shape == (6,) and e.input.dtype == np.float64
        np.testing.assert_allclose(e.input, cli_reference.raw(e.frame), rtol=0, atol=TOL,
                                   err_msg=f"frame {e.frame}")
    depths = [e.input[2] for e in inputs]
    assert max(depths) > 2.0  # the press goes 2.5 mm deep: the 6-D input really moved


def test_callbacks_run_on_the_processing_thread_and_see_the_same_events(press):
    assert press.callback_threads and threading.get_ident() not in press.callback_threads
    assert [(e.type, e.frame) for e in press.callback_events] == [(e.type, e.frame) for e in press.polled_events]
    for a, b in zip(press.callback_events, press.polled_events):
        np.testing.assert_array_equal(a.input, b.input)


def test_frame_results_match_the_cpp_pose_and_markers(press, cli_reference):
    processed = [f for f in press.frames if f.status in (onetip.FrameStatus.ok, onetip.FrameStatus.reference)]
    assert [f.frame for f in processed] == sorted(cli_reference.pose)
    for f in processed:
        np.testing.assert_allclose(f.raw, cli_reference.raw(f.frame), rtol=0, atol=TOL, err_msg=f"frame {f.frame}")
        assert f.contact == (cli_reference.pose[f.frame]["contact"] == "1")
        expected = np.array(cli_reference.markers[f.frame])
        assert f.markers.shape == expected.shape and f.markers.shape[1] == 4
        np.testing.assert_array_equal(f.markers[:, 0], expected[:, 0])
        np.testing.assert_allclose(f.markers[:, 1:], expected[:, 1:], rtol=0, atol=TOL)


def test_contact_field_is_the_motion_of_each_marker_from_rest(press):
    rest = press.frames[0]
    assert rest.status == onetip.FrameStatus.reference
    deepest = max(press.frames, key=lambda f: f.max_normal_mm)
    n = deepest.rows * deepest.cols
    assert deepest.positions.shape == (n, 3) and deepest.displacements.shape == (n, 3)
    known = deepest.displaced & rest.valid
    assert known.sum() > n // 2
    # from the rest kept true while nothing touches: it follows slow drift by a fraction of the marker noise
    # (0.0006 mm) per frame, within five times that noise of the reference frame
    np.testing.assert_allclose(deepest.displacements[known], deepest.positions[known] - rest.positions[known],
                               rtol=0, atol=0.003)
    assert np.isnan(deepest.displacements[~deepest.displaced]).all()
    # the pad is pushed in (-z in S) under the finger, by up to about the press depth
    assert -np.nanmin(deepest.displacements[:, 2]) > 2.0
    assert (deepest.regions[known] >= 0).any() and (deepest.regions[~deepest.valid] == -1).all()


def test_stats_count_every_frame(press, cli_reference):
    assert press.stats.frames_processed == len(cli_reference.pose)
    assert press.stats.frames_dropped == 0 and press.stats.callback_errors == 0
    stages = {s.stage: s for s in press.stats.stages}
    assert stages["process"].count == len(cli_reference.pose) and stages["process"].median_ms > 0


def test_frame_sd_equals_the_sd_columns_of_pose_csv(press, cli_reference):
    processed = [f for f in press.frames if f.status in (onetip.FrameStatus.ok, onetip.FrameStatus.reference)]
    assert len(processed) == len(cli_reference.pose)
    for f in processed:
        assert f.sd.shape == (6,) and f.sd.dtype == np.float64
        np.testing.assert_allclose(f.sd, cli_reference.sd(f.frame), rtol=0, atol=TOL, err_msg=f"frame {f.frame}")
        if not f.contact:
            np.testing.assert_array_equal(f.sd, np.zeros(6), err_msg=f"frame {f.frame} out of contact")


def test_events_carry_the_sd_of_their_frame(press):
    sd_of = {f.frame: f.sd for f in press.frames}
    inputs = press.of_type(onetip.EventType.input)
    assert inputs
    for e in inputs:
        assert e.sd.shape == (6,)
        np.testing.assert_array_equal(e.sd, sd_of[e.frame], err_msg=f"frame {e.frame}")
    for a, b in zip(press.callback_events, press.polled_events):
        np.testing.assert_array_equal(a.sd, b.sd)


def test_stick_probability_is_one_value_in_0_1_per_marker_and_0_out_of_contact(press):
    for f in press.frames:
        p = f.stick_probability
        assert p.shape == (f.rows * f.cols,) and p.dtype == np.float64
        assert ((p >= 0) & (p <= 1)).all(), f"frame {f.frame}"
        if not f.contact:
            assert (p == 0).all(), f"frame {f.frame} out of contact"
