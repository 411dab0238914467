"""The pose uncertainty in contact through the Python module (run on its own:
ctest python_uncertainty_in_contact). Needs the estimator's uncertainty
(pose/pose_uncertainty): until it lands every sd is 0 and this fails."""


def test_contact_frames_have_a_positive_sd_and_sticking_markers(press):
    """Needs the estimator's uncertainty (pose/pose_uncertainty): until then every sd is 0."""
    contact = [f for f in press.frames if f.contact]
    assert len(contact) > 20
    for f in contact:
        assert (f.sd > 0).all(), f"frame {f.frame}: sd {f.sd}"
        assert f.stick_probability.max() > 0, f"frame {f.frame}: no marker sticks"
