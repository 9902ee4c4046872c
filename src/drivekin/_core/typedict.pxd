# Adding attributes to the dict of a Cython extension type (a static type, whose dict
# Python code cannot assign): WPILib's constants (Rotation2d.kZero, ...) and the
# Python-level __new__ of the wheel value classes (_wheels.install_bare_new).
cdef extern from *:
    """
    static int drivekin_set_type_attr(PyObject *t, PyObject *name, PyObject *v) {
        int r = PyDict_SetItem(((PyTypeObject *)t)->tp_dict, name, v);
        PyType_Modified((PyTypeObject *)t);
        return r;
    }
    /* The type's own tp_new slot: the Cython constructor of exactly that class. */
    static PyObject *drivekin_slot_new(PyObject *t) {
        PyObject *args = PyTuple_New(0);
        PyObject *o;
        if (args == NULL) return NULL;
        o = ((PyTypeObject *)t)->tp_new((PyTypeObject *)t, args, NULL);
        Py_DECREF(args);
        return o;
    }
    """
    int drivekin_set_type_attr(object t, object name, object v) except -1
    object drivekin_slot_new(object t)
