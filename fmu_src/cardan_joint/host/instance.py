"""One FMU instance (FMI 2.0 or 3.0) on FMPy's low-level API, its Float variables by name.

The one wrapper around FMPy's slave classes that tests, examples and benchmarks
share: initialisation with start values, set/get by name, stepping (raising
the FMU's own reason, or returning the status), FMU states, an optional log
sink, terminate/free on leaving `with`. It knows no model: names come from
the FMU's model description. Ctrl-C (SIGTERM, SIGHUP) during a call into the FMU
raises KeyboardInterrupt when the call is over (`interrupts.STEP_INTERRUPTS`),
never a refusal.

    with FmuInstance.open("dist/<Model>.fmu", start_values={...}) as model:
        model.step(1e-3)
        model.get("output_speed")

    with ExtractedFMU("dist/<Model>.fmu") as fmu:      # unzipped once
        with fmu.instance("first") as one, fmu.instance("second") as two: ...
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from ..names import check_known
from .fmpy_slave import fmpy_slave, logging_callbacks
from .fmu_info import FmuInfo
from .interrupts import STEP_INTERRUPTS
from .unpacked import ExtractedFMU

Message = tuple[int, str, str]  # (FMI status, category, text)
# FMPy's opaque handle of a saved FMU state (fmi2FMUstate / fmi3FMUState pointer).
FMUState = Any


# FmuInstance hides FMI 3's call sequence, array getters and FMU-state names.
_VERSIONS = ("2.0", "3.0")


class _Recent(list):
    """The current call's log messages, each also passed on to the user's sink."""

    def __init__(self, also: Any) -> None:
        super().__init__()
        self.also = also

    def append(self, message: Message) -> None:
        super().append(message)
        if self.also is not None:
            self.also.append(message)


def status_of(call, *args, **kwargs) -> int:
    """The FMI status of a call FMPy raises on (fmi2Discard or worse), 0 for OK."""
    from fmpy.fmi1 import FMICallException

    try:
        call(*args, **kwargs)
        return 0
    except (FMICallException, StepRefusedError) as refusal:
        return refusal.status


class StepRefusedError(RuntimeError):
    """A refused step: the FMU's own reason (variable, value, limit, time), its FMI `status`."""

    def __init__(self, text: str, status: int) -> None:
        super().__init__(text)
        self.status = status


class FmuInstance:
    """One instance of an unzipped FMU, initialised and ready to step from `start_time`.

    `messages`: a list (anything with `append`) that also receives the FMU's
    log messages as (status, category, text). Logging is always on (pythonfmu
    forwards nothing otherwise): a refused step raises with the FMU's reason.
    `exit_initialization=False`
    leaves it in Initialization Mode (start values set) until
    `exit_initialization_mode()`.
    """

    def __init__(
        self,
        model_description: Any,
        unzipped: str | Path,
        name: str = "instance",
        start_values: dict[str, float] | None = None,
        start_time: float = 0.0,
        messages: Any = None,
        exit_initialization: bool = True,
    ) -> None:
        version = model_description.fmiVersion
        if version not in _VERSIONS:
            raise ValueError(
                f"FMI version {version} of {model_description.modelName!r} is not "
                f"supported; supported: {', '.join(_VERSIONS)}"
            )
        self.model_description = model_description
        self.info = FmuInfo(model_description)
        self.references = {v.name: v.valueReference for v in model_description.modelVariables}
        self.outputs = self.info.outputs
        self.fmi3 = self.info.fmi3
        # Elements per variable (FMI 3 arrays; 1 for a scalar).
        self.sizes = {name: v.size for name, v in self.info.variables.items()}
        self.fmu = fmpy_slave(model_description, str(unzipped), name)
        self._cleanup: list[Callable[[], None]] = []
        # The messages of the current call only: a refused step raises with them.
        self.recent = sink = _Recent(messages)
        STEP_INTERRUPTS.acquire()
        self._holding = True
        try:
            with self._calling():
                self._instantiate(sink)
            with self._calling():
                if self.fmi3:
                    self.fmu.enterInitializationMode(startTime=start_time)
                else:
                    self.fmu.setupExperiment(startTime=start_time)
                    self.fmu.enterInitializationMode()
            if start_values:
                self.set(**start_values)
            self.time = start_time
            if exit_initialization:
                self.exit_initialization_mode()
        except BaseException:
            self.close()
            raise

    def _instantiate(self, sink: Any) -> None:
        if self.fmi3:
            # FMPy keeps the callback on the FMU object, so it outlives the instance.
            self.callbacks = None
            self.fmu.instantiate(
                logMessage=lambda env, status, category, message: sink.append(
                    (status, category.decode(), message.decode())
                )
            )
        else:
            # Kept on the instance: ctypes callbacks must outlive the FMU.
            self.callbacks = logging_callbacks(sink)
            self.fmu.instantiate(callbacks=self.callbacks, loggingOn=True)
        self._cleanup.append(self.fmu.freeInstance)

    @contextmanager
    def _calling(self) -> Iterator[None]:
        """The block's calls into the FMU with the stop signals held: one that
        comes during a call is raised after it. Inside, Python would run its
        handler wherever the call runs Python code: in the FMU's own (the
        runtime then fails the call, and the instance with it) or in the
        logger's callback (ctypes prints the exception and drops it)."""
        held = STEP_INTERRUPTS.request
        held.holding = True
        try:
            yield
        finally:
            held.holding = False
            held.raise_requested()

    def exit_initialization_mode(self) -> int:
        """Leave initialization; the FMI status is kept as `init_status` (fmi2Error
        for parameters that cannot run: the instance stays usable, every step is
        refused until they are fixed)."""
        with self._calling():
            self.init_status = status_of(self.fmu.exitInitializationMode)
            self._cleanup.append(self.fmu.terminate)  # before a held Ctrl-C is raised
        return self.init_status

    @classmethod
    def open(cls, fmu: str | Path, **arguments) -> FmuInstance:
        """An instance of an .fmu file (unzipped here, removed on close) or of an
        unzipped FMU directory (left alone); MissingFMUError names the build command."""
        extracted = ExtractedFMU(fmu)
        try:
            instance = cls(extracted.model_description, extracted.directory, **arguments)
        except BaseException:
            extracted.close()
            raise
        instance._cleanup.insert(0, extracted.close)
        return instance

    def __enter__(self) -> FmuInstance:
        return self

    def __exit__(self, kind, error, traceback) -> None:
        if error is None:
            self.close()
            return
        # A block that raised (Ctrl-C handed back from inside a call) leaves the
        # instance in the error state, where terminate fails: that failure is
        # a note on the block's exception, which goes on as it was.
        try:
            self.close()
        except Exception as failure:
            error.add_note(f"closing {self.fmu.instanceName!r} then failed too: {failure}")

    def _refs(self, names: Iterable[str]) -> list[int]:
        names = list(names)
        check_known(names, self.references, f"variable of {self.info.model_name}")
        return [self.references[n] for n in names]

    def set(self, **values: float) -> None:
        setter = self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal
        with self._calling():
            setter(self._refs(values), list(values.values()))

    def values(self, *names: str) -> list:
        """The variables' values, in the order named; an FMI 3 array comes as a list."""
        with self._calling():
            if not self.fmi3:
                return self.fmu.getReal(self._refs(names))
            read = self.fmu.getFloat64(self._refs(names), sum(self.sizes[n] for n in names))
        flat = iter(read)
        return [
            [next(flat) for _ in range(self.sizes[n])] if self.sizes[n] > 1 else next(flat)
            for n in names
        ]

    def get(self, *names: str) -> dict[str, float]:
        return dict(zip(names, self.values(*names)))

    def get_outputs(self) -> dict[str, float]:
        return self.get(*self.outputs)

    def get_flat_outputs(self) -> dict[str, float]:
        """Every output by its FMI 2 name (an FMI 3 array split into its rows)."""
        values: dict[str, float] = {}
        for name, value in self.get_outputs().items():
            columns = self.info.variables[name].columns
            values.update(zip(columns, value) if isinstance(value, list) else [(name, value)])
        return values

    def step(self, step_size: float) -> None:
        """Step from `self.time`; a refusal raises StepRefusedError: the FMU's reason."""
        from fmpy.fmi1 import FMICallException

        self.recent.clear()
        with self._calling():  # a second Ctrl-C fails the step: it is raised, not the refusal
            try:
                self.fmu.doStep(
                    currentCommunicationPoint=self.time, communicationStepSize=step_size
                )
            except FMICallException as refused:
                reasons = [text for status, _, text in self.recent if status >= 2] or [
                    f"(the FMU gave no reason; {refused})"
                ]
                raise StepRefusedError(
                    f"{self.info.model_name} refused the step at t = {self.time:.9g} s: "
                    + "; ".join(reasons),
                    refused.status,
                ) from None
            self.time += step_size

    def try_step(self, step_size: float) -> int:
        """Step; return the FMI status (a refused step leaves the time where it was)."""
        return status_of(self.step, step_size)

    def try_set(self, **values: float) -> int:
        """Set; return the FMI status (fmi2Error for a call FMI does not allow)."""
        return status_of(self.set, **values)

    def _state_call(self, fmi2: str, fmi3: str, *args: Any) -> Any:
        """An FMU-state call by its FMI 2 or FMI 3 name."""
        with self._calling():
            return getattr(self.fmu, fmi3 if self.fmi3 else fmi2)(*args)

    def get_state(self) -> FMUState:
        return self._state_call("getFMUstate", "getFMUState")

    def set_state(self, state: FMUState) -> None:
        self._state_call("setFMUstate", "setFMUState", state)

    def free_state(self, state: FMUState) -> None:
        self._state_call("freeFMUstate", "freeFMUState", state)

    def serialize_state(self, state: FMUState) -> bytes:
        return bytes(self._state_call("serializeFMUstate", "serializeFMUState", state))

    def deserialize_state(self, serialized: bytes) -> FMUState:
        return self._state_call("deSerializeFMUstate", "deserializeFMUState", serialized)

    def close(self) -> None:
        """Terminate and free the instance (and remove what `open` unzipped); once."""
        try:
            self._clean_up()
        finally:
            if getattr(self, "_holding", False):
                self._holding = False
                STEP_INTERRUPTS.release()

    def _clean_up(self) -> None:
        if self._cleanup:
            action = self._cleanup.pop()
            try:
                with self._calling():
                    action()
            finally:  # the rest runs even when one step fails
                self._clean_up()
