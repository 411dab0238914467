"""The pose uncertainty in contact through the Python module (run on its own:
ctest python_uncertainty_in_contact)."""


def test_contact_frames_have_a_positive_sd_and_sticking_markers(press):
    """After the onset (where the input is zero by definition, its sd 0) every axis has a positive sd."""
    contact = [f for f, before in zip(press.frames[1:], press.frames) if f.contact and before.contact]
    assert len(contact) > 20
    for f in contact:
        assert (f.sd > 0).all(), f"frame {f.frame}: sd {f.sd}"
        assert f.stick_probability.max() > 0, f"frame {f.frame}: no marker sticks"
